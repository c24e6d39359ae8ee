#pragma once

#include "scenegraph/Node.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace texsplat::bench {

/// @brief One row of measureTransferEdit(): a transfer-function edit and the frame after it.
struct TransferEditTime {
    std::string edit;            ///< what was changed, in words
    std::uint64_t maxSplats = 0; ///< the splat nodes' budget (0: full resolution)
    std::size_t splats = 0;      ///< splats drawn by the frame after the edit
    double editSeconds = 0.0;    ///< that frame, on the scene that drew the frame before
    double rebuildSeconds = 0.0; ///< the same frame on a fresh copy of the scene (new caches)
    double valueRangeSeconds = 0.0; ///< of rebuildSeconds: making the grids' value ranges
    std::size_t editValueRanges = 0; ///< value ranges the edited frame made (0: none rebuilt)
};

/// @brief Times what a transfer-function edit costs (docs/results/big-volumes.md): for each
/// budget of `maxSplats` (0: full resolution) and each of two edits of every TransferFunction of
/// the scene — "opacities x 0.5" (what is visible stays so) and "range from 30 %" (the lower 30 %
/// of `range` becomes transparent; the range becomes FIXED) — the wall time of the next CPU frame
/// after the edit on a scene that already drew a frame, against the same frame of a fresh copy of
/// the scene (`makeScene()` again: new splat nodes and caches; the grids are shared loads, so
/// loading is not counted). The latter is what an edit cost before value ranges existed, plus
/// making the ranges (`valueRangeSeconds`, timed apart).
/// @throws DataError when the scene has no TransferFunction or no splat node; what rendering
/// throws.
std::vector<TransferEditTime> measureTransferEdit(const std::function<sg::Node::Ptr()>& makeScene,
                                                  glm::ivec2 size,
                                                  const std::vector<std::uint64_t>& maxSplats,
                                                  int threads);

/// @brief measureTransferEdit()'s rows as a text table.
std::string transferEditTable(const std::vector<TransferEditTime>& rows);

} // namespace texsplat::bench
