#pragma once

namespace texsplat::sg {

/// @brief The largest coordinate, in magnitude, that texsplat draws: positions are single
/// precision, and the squares and products that framing and projection take of them must stay
/// finite (FLT_MAX is about 3.4e38). Volumes and framed scenes beyond it are refused with this
/// number in the message.
constexpr double kMaxCoordinate = 1e18;

} // namespace texsplat::sg
