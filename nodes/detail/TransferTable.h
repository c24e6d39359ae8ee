#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace texsplat::nodes::detail {

/// @brief Piecewise-linear control points: values `x()` (not decreasing) and what they map to;
/// constant beyond the first and last point. Equal neighbouring x make a step.
///
/// A lookup finds its segment from a uniform index over [x.front, x.back] and a step or two
/// along x, not by a binary search: a colour map has 256 points, and the search's eight
/// unpredictable branches were most of a voxel's classification. The segment, and so the value,
/// is the binary search's, bit for bit.
template <class Y> class PiecewiseLinear {
public:
    /// @brief No points: give some before a lookup.
    PiecewiseLinear() = default;
    /// @brief The map through (x[i], y[i]): x not decreasing, both the same size.
    PiecewiseLinear(std::vector<float> x, std::vector<Y> y);

    /// @brief The interpolated value at `t` (x and y non-empty, same size).
    Y operator()(float t) const;

    /// @brief The control points' positions.
    const std::vector<float>& x() const { return mX; }
    /// @brief What they map to.
    const std::vector<Y>& y() const { return mY; }

private:
    std::vector<float> mX;
    std::vector<Y> mY;
    // Per cell of [x.front, x.back] (mCellsPerUnit cells per unit of x): the first i with
    // x[i] > the cell's lower edge.
    std::vector<std::uint32_t> mCellStart;
    float mCellsPerUnit = 0.0f;
};

extern template class PiecewiseLinear<float>;
extern template class PiecewiseLinear<glm::vec3>;

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
