#include "scenegraph/fields/ValueFormat.h"

#include <array>
#include <charconv>

namespace texsplat::sg {

namespace {

// std::to_chars without a precision gives the shortest text that parses back exactly.
template <class Number> std::string shortestText(Number value) {
    std::array<char, 32> buffer{};
    const std::to_chars_result result =
        std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

} // namespace

std::string formatFloat(float value) { return shortestText(value); }

std::string formatDouble(double value) { return shortestText(value); }

std::string formatString(std::string_view text) {
    std::string quoted;
    quoted.reserve(text.size() + 2);
    quoted += '"';
    for (char c : text) {
        if (c == '"' || c == '\\') {
            quoted += '\\';
        }
        quoted += c;
    }
    quoted += '"';
    return quoted;
}

} // namespace texsplat::sg
