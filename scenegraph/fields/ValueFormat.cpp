#include "scenegraph/fields/ValueFormat.h"

#include <array>
#include <charconv>

namespace texsplat::sg {

std::string formatFloat(float value) {
    // std::to_chars without a precision gives the shortest text that parses back exactly.
    std::array<char, 32> buffer{};
    const std::to_chars_result result =
        std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

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
