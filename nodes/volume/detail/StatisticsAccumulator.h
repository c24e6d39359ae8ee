#pragma once

#include "nodes/volume/Grid.h"

#include <algorithm>
#include <limits>

namespace texsplat::volume::detail {

/// @brief Grid::statistics() one stored voxel at a time, for every grid's way of walking them.
template <typename T> class StatisticsAccumulator {
public:
    /// @brief Counts one stored voxel.
    void add(const T& value) {
        if (!isFiniteValue(value)) {
            ++mResult.nonFiniteCount;
            return;
        }
        ++mResult.finiteCount;
        const double magnitude = magnitudeOf(value);
        mLowest = std::min(mLowest, magnitude);
        mHighest = std::max(mHighest, magnitude);
    }

    /// @brief What the voxels added so far give.
    GridStatistics result() const {
        GridStatistics result = mResult;
        if (result.finiteCount > 0) {
            result.minimum = mLowest;
            result.maximum = mHighest;
        }
        return result;
    }

private:
    static double magnitudeOf(float value) { return value; }
    static double magnitudeOf(const glm::vec3& value) {
        return glm::length(glm::dvec3(value));
    }

    GridStatistics mResult;
    double mLowest = std::numeric_limits<double>::infinity();
    double mHighest = -std::numeric_limits<double>::infinity();
};

} // namespace texsplat::volume::detail
