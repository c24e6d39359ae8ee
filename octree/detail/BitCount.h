#pragma once

#include <array>
#include <cstdint>

namespace texsplat::octree::detail {

/// @brief The number of set bits of each 8-bit child mask.
inline constexpr std::array<std::uint8_t, 256> kBitCounts = [] {
    std::array<std::uint8_t, 256> counts{};
    for (unsigned mask = 1; mask < 256; ++mask) {
        counts[mask] = static_cast<std::uint8_t>(counts[mask >> 1] + (mask & 1u));
    }
    return counts;
}();

/// @brief The number of set bits of @p mask (8 bits: a node's children). From a table: built
/// for any x86-64, the compiler's population count is a call into libgcc, which took a twentieth
/// of an octree cut's emission.
constexpr int bitCount(std::uint8_t mask) { return kBitCounts[mask]; }

} // namespace texsplat::octree::detail
