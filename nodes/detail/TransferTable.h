#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace texsplat::nodes::detail {

/// @brief Piecewise-linear control points: values `x` (not decreasing) and what they map to;
/// constant beyond the first and last point. Equal neighbouring x make a step.
template <class Y> struct PiecewiseLinear {
    std::vector<float> x;
    std::vector<Y> y;

    /// @brief The interpolated value at `t` (x and y non-empty, same size).
    Y operator()(float t) const;
};

extern template struct PiecewiseLinear<float>;
extern template struct PiecewiseLinear<glm::vec3>;

/// @brief A TransferFunction's fields, checked and ready for fast, thread-safe lookups.
struct TransferTable {
    float rangeMin = 0.0f; ///< the `range` field
    float rangeMax = 1.0f;
    int rangeMode = 0;                    ///< nodes::RangeMode, never Auto (resolved)
    glm::dvec2 percentiles{1.0, 99.0};    ///< in percent
    float unitDistance = 1.0f;            ///< 0: one voxel
    PiecewiseLinear<glm::vec3> colors;
    PiecewiseLinear<float> opacities;
    float emission = 0.0f;
};

/// @brief The colour control points of a named preset over t in [0, 1] (preset is the int value
/// of nodes::ColorPreset).
PiecewiseLinear<glm::vec3> presetColors(int preset);

} // namespace texsplat::nodes::detail
