#pragma once

#include "nodes/volume/Grid.h"

#include <glm/vec2.hpp>

namespace texsplat::nodes::detail {

/// @brief The smallest and largest finite value of `grid` (for vectors: magnitude), widened to
/// [v - 0.5, v + 0.5] when all values are v, and [0, 1] when there is none: a range a transfer
/// function can normalize over.
template <class T> glm::dvec2 valueRange(const volume::Grid<T>& grid);

/// @brief [`low`, `high`] as valueRange() widens it: [v - 0.5, v + 0.5] when both are v.
glm::dvec2 widenedRange(double low, double high);

/// @brief The `low` and `high` percentiles (in [0, 100], low < high) of the finite values of
/// `grid` (for vectors: magnitudes), within 1 / 65536 of the value range (a histogram of that
/// many bins, so that memory stays small for huge grids); widened as valueRange() when they
/// are equal. For a brick, the whole grid's (from its WholeGrid histogram).
template <class T> glm::dvec2 percentileRange(const volume::Grid<T>& grid, double low, double high);

extern template glm::dvec2 valueRange(const volume::Grid<float>&);
extern template glm::dvec2 valueRange(const volume::Grid<glm::vec3>&);
extern template glm::dvec2 percentileRange(const volume::Grid<float>&, double, double);
extern template glm::dvec2 percentileRange(const volume::Grid<glm::vec3>&, double, double);

} // namespace texsplat::nodes::detail
