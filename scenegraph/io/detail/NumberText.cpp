#include "scenegraph/io/detail/NumberText.h"

#include <cctype>
#include <charconv>
#include <cstddef>
#include <limits>

namespace texsplat::sg::detail {

namespace {

std::size_t skipDigits(std::string_view text, std::size_t i) {
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) != 0) {
        ++i;
    }
    return i;
}

} // namespace

bool isFloatText(std::string_view text) {
    std::size_t i = (!text.empty() && (text[0] == '-' || text[0] == '+')) ? 1 : 0;
    if (text.substr(i) == "inf" || text.substr(i) == "nan") {
        return true;
    }
    const std::size_t integerEnd = skipDigits(text, i);
    std::size_t end = integerEnd;
    bool hasDigits = integerEnd > i;
    if (end < text.size() && text[end] == '.') {
        const std::size_t fractionEnd = skipDigits(text, end + 1);
        hasDigits = hasDigits || fractionEnd > end + 1;
        end = fractionEnd;
    }
    if (hasDigits && end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
        std::size_t exponent = end + 1;
        if (exponent < text.size() && (text[exponent] == '-' || text[exponent] == '+')) {
            ++exponent;
        }
        end = skipDigits(text, exponent);
        hasDigits = end > exponent;
    }
    return hasDigits && end == text.size();
}

IntegerText parseInt32(std::string_view text, std::int32_t& value) {
    const bool isNegative = !text.empty() && text.front() == '-';
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
        text.remove_prefix(1);
    }
    int base = 10;
    if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        text.remove_prefix(2);
        base = 16;
    }
    std::uint64_t magnitude = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), magnitude, base);
    if (text.empty() || end != text.data() + text.size() || error == std::errc::invalid_argument) {
        return IntegerText::Malformed;
    }
    // The most negative int32 has one more unit of magnitude than the most positive.
    const std::uint64_t limit =
        std::uint64_t{std::numeric_limits<std::int32_t>::max()} + (isNegative ? 1 : 0);
    if (error == std::errc::result_out_of_range || magnitude > limit) {
        return IntegerText::OutOfRange;
    }
    const auto signedMagnitude = static_cast<std::int64_t>(magnitude);
    value = static_cast<std::int32_t>(isNegative ? -signedMagnitude : signedMagnitude);
    return IntegerText::Valid;
}

} // namespace texsplat::sg::detail
