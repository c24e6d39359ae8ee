#include "scenegraph/sensors/detail/FormatTime.h"

#include "scenegraph/fields/ValueFormat.h"

#include <cmath>

namespace texsplat::sg::detail {

std::string formatTime(double seconds) {
    return std::isnan(seconds) ? "nan" : formatDouble(seconds);
}

} // namespace texsplat::sg::detail
