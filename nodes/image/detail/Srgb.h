#pragma once

#include <cmath>

namespace texsplat::image::detail {

/// @brief The sRGB transfer function (IEC 61966-2-1): linear [0, 1] → encoded [0, 1].
inline float linearToSrgb(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear
                                : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

/// @brief The inverse sRGB transfer function: encoded [0, 1] → linear [0, 1].
inline float srgbToLinear(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f
                               : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

} // namespace texsplat::image::detail
