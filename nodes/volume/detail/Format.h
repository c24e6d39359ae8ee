#pragma once

#include <cstdlib>
#include <sstream>
#include <string>

namespace texsplat::volume::detail {

/// @brief Shortest text that reads back as the same double, for messages ("0.05", "-1", "nan",
/// "inf"), so users see the number they wrote rather than its binary expansion.
inline std::string formatNumber(double value) {
    std::string text;
    for (int precision = 6; precision <= 17; ++precision) {
        std::ostringstream out;
        out.precision(precision);
        out << value;
        text = out.str();
        if (std::strtod(text.c_str(), nullptr) == value)
            break;
    }
    return text;
}

} // namespace texsplat::volume::detail
