#include "scenegraph/io/detail/NumberText.h"

#include <algorithm>
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

// For a valid number outside the range of float: true when it is below the smallest denormal
// rather than above the largest float. The power of ten of its first significant digit decides,
// since the range reaches from about 1e-45 to 3.4e38.
bool isBelowFloatRange(std::string_view text) {
    std::size_t i = (text[0] == '-' || text[0] == '+') ? 1 : 0;
    std::int64_t power = 0;
    bool isSignificant = false;
    bool isFraction = false;
    for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
        if (text[i] == '.') {
            isFraction = true;
        } else if (isFraction && !isSignificant) {
            --power;
            isSignificant = text[i] != '0';
        } else if (!isFraction && (isSignificant || text[i] != '0')) {
            power += isSignificant ? 1 : 0;
            isSignificant = true;
        }
    }
    std::int64_t exponent = 0;
    bool isNegative = false;
    if (i < text.size()) {
        ++i; // past 'e'; a digit follows, after an optional sign
        isNegative = text[i] == '-';
        i += (text[i] == '-' || text[i] == '+') ? 1 : 0;
        for (; i < text.size(); ++i) {
            // Saturated beyond any mantissa's length, so that it still decides.
            constexpr std::int64_t kSaturated = 1'000'000'000'000'000;
            exponent = std::min<std::int64_t>(exponent * 10 + (text[i] - '0'), kSaturated);
        }
    }
    return power + (isNegative ? -exponent : exponent) < 0;
}

} // namespace

ParsedNumber parseFloat(std::string_view text, float& value) {
    if (!isFloatText(text)) {
        return ParsedNumber::Malformed;
    }
    // std::from_chars ignores the locale; it takes no '+'.
    const std::string_view number = text.front() == '+' ? text.substr(1) : text;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error == std::errc::result_out_of_range) {
        if (!isBelowFloatRange(number)) {
            return ParsedNumber::OutOfRange;
        }
        value = number.front() == '-' ? -0.0f : 0.0f;
    } else if (error != std::errc() || end != number.data() + number.size()) {
        return ParsedNumber::Malformed;
    }
    return ParsedNumber::Valid;
}

ParsedNumber parseInt32(std::string_view text, std::int32_t& value) {
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
        return ParsedNumber::Malformed;
    }
    // The most negative int32 has one more unit of magnitude than the most positive.
    const std::uint64_t limit =
        std::uint64_t{std::numeric_limits<std::int32_t>::max()} + (isNegative ? 1 : 0);
    if (error == std::errc::result_out_of_range || magnitude > limit) {
        return ParsedNumber::OutOfRange;
    }
    const auto signedMagnitude = static_cast<std::int64_t>(magnitude);
    value = static_cast<std::int32_t>(isNegative ? -signedMagnitude : signedMagnitude);
    return ParsedNumber::Valid;
}

} // namespace texsplat::sg::detail
