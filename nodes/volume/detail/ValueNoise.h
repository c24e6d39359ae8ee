#pragma once

#include "scenegraph/Random.h"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>

namespace texsplat::volume::detail {

/// @brief Smooth, seeded value noise in [0, 1): random values on the integer lattice, blended
/// with smoothstep weights. Stateless (a hash of seed and lattice point), so it is deterministic
/// and needs no tables.
inline double valueNoise(const glm::dvec3& position, std::uint64_t seed) {
    const glm::dvec3 cell = glm::floor(position);
    const glm::dvec3 f = position - cell;
    const glm::dvec3 w = f * f * (3.0 - 2.0 * f);
    const auto lattice = [&](int dx, int dy, int dz) {
        std::uint64_t h = sg::Random::mix(seed);
        h = sg::Random::mix(h ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(cell.x) + dx));
        h = sg::Random::mix(h ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(cell.y) + dy));
        h = sg::Random::mix(h ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(cell.z) + dz));
        return double(h >> 11) * 0x1.0p-53;
    };
    double result = 0.0;
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx)
                result += (dx ? w.x : 1.0 - w.x) * (dy ? w.y : 1.0 - w.y) *
                          (dz ? w.z : 1.0 - w.z) * lattice(dx, dy, dz);
    return result;
}

} // namespace texsplat::volume::detail
