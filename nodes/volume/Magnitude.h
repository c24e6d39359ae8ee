#pragma once

#include "nodes/volume/Grid.h"

namespace texsplat::volume {

/// @brief The scalar grid of vector magnitudes |v|, for classifying and coloring vector fields
/// (paper, Figures 5-7: opacity from the magnitude).
///
/// The result has the same geometry and the same storage as `vectors`: a sparse grid stays sparse
/// and keeps its active voxels. Empty (non-finite) vectors give empty (NaN) magnitudes. A finite
/// vector whose length exceeds the float range gets the largest finite float, so it stays
/// non-empty.
ScalarGridPtr magnitudeGrid(const VectorGrid& vectors);

} // namespace texsplat::volume
