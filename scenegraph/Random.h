#pragma once

#include <cstdint>

namespace texsplat::sg {

/// @brief SplitMix64 (Steele, Lea & Flood 2014): a tiny generator whose output is fully
/// specified, so seeded generators give the same data on every platform and standard library
/// (std::uniform_real_distribution does not promise that): the volume generators, the vector
/// splat table's marks, the vector splats' random rows, the noisy colour map.
class Random {
public:
    /// @brief A generator started from `seed`.
    explicit Random(std::uint64_t seed) : mState(seed) {}

    /// @brief The next 64 random bits.
    std::uint64_t nextBits() {
        mState += 0x9E3779B97F4A7C15ull;
        return mix(mState);
    }
    /// @brief Uniform in [0, 1), from the top 53 bits.
    double uniform() { return double(nextBits() >> 11) * 0x1.0p-53; }
    /// @brief Uniform in [low, high).
    double uniform(double low, double high) { return low + (high - low) * uniform(); }

    /// @brief SplitMix64's finalizer: a bijective scramble of 64 bits, also used as a hash.
    static std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

private:
    std::uint64_t mState;
};

} // namespace texsplat::sg
