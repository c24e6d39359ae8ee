#include "scenegraph/sensors/detail/FormatTime.h"

#include <array>
#include <charconv>
#include <cmath>

namespace texsplat::sg::detail {

std::string formatTime(double seconds) {
    if (std::isnan(seconds)) {
        return "nan";
    }
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), seconds);
    return std::string(buffer.data(), result.ptr);
}

} // namespace texsplat::sg::detail
