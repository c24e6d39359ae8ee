#pragma once

#include "scenegraph/Node.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace texsplat::bench {

/// @brief One row of measureTransferEdit(): a transfer-function edit and the frame after it.
struct TransferEditTime {
    std::string edit;            ///< what was changed, in words
    std::uint64_t maxSplats = 0; ///< the splat nodes' budget (0: full resolution)
    std::size_t splats = 0;      ///< splats drawn by the frame after the edit
    double editSeconds = 0.0;    ///< that frame, on the scene that drew the frame before
    /// @brief The same frame as the path before value ranges took it: the frame's ordering and
    /// drawing, plus classifying every voxel of the grid with the edited function (no block
    /// skipped, a DATA range scanned) and, with a budget, building the octree over that.
    double reclassifySeconds = 0.0;
    /// @brief The interactive frame after the same edit (render::FrameAction::setInteractive()):
    /// the edit's preview from the blocks' value histograms, which classifies no voxel.
    double previewSeconds = 0.0;
    std::size_t previewSplats = 0;   ///< splats that preview drew
    /// @brief RGB PSNR (dB, peak 1) against the full-resolution frame after the same edit, of
    /// the exact frame at this budget (infinite at full resolution) and of the preview; NaN when
    /// no full-resolution frame of the edit was measured before (budgets without a 0 first).
    double editPsnr = 0.0;
    double previewPsnr = 0.0;
    double valueRangeSeconds = 0.0;  ///< making the grid's value ranges once (the first frame)
    double valueHistogramSeconds = 0.0; ///< its block value histograms (once, the first preview)
    std::size_t editValueRanges = 0; ///< value ranges the edited frame made (0: none rebuilt)
};

/// @brief Times what a transfer-function edit costs (docs/results/big-volumes.md): for each
/// budget of `maxSplats` (0: full resolution) and each of two edits of the scene's transfer
/// functions — "opacities x 0.5" (what is visible stays so) and "range from 30 %" (the lower 30 %
/// of `range` becomes transparent; the range becomes FIXED) — the wall time of the next CPU frame
/// after the edit on a scene that already drew a frame (loading not counted), against the same
/// frame with the classification (and octree) made as before value ranges existed: every voxel
/// of the first VolumeData's grid classified by the first TransferFunction; and the interactive
/// frame right after the edit, its preview (timed before the exact frame, which it does not
/// make faster: a preview classifies nothing; the grid's block value histograms, made for the
/// first preview, are made before the first row and timed on their own).
/// With an `imageFolder`, the two frames after each edit are written there as PNGs for a look:
/// `<edit>-<budget>-exact.png` and `<edit>-<budget>-preview.png`, `<edit>` being
/// `opacities-half` or `range-from-30`, `<budget>` `full` or the number.
/// @throws DataError when the scene has no TransferFunction, VolumeData or splat node; IoError
/// when an image cannot be written; what rendering throws.
std::vector<TransferEditTime> measureTransferEdit(const sg::Node::Ptr& scene, glm::ivec2 size,
                                                  const std::vector<std::uint64_t>& maxSplats,
                                                  int threads,
                                                  const std::string& imageFolder = {});

/// @brief Where measureTransferEdit() writes the `kind` ("exact" or "preview") frame after the
/// first edit at full resolution in `imageFolder`: for a check before the long run.
std::string transferEditImagePath(const std::string& imageFolder, const std::string& kind);

/// @brief measureTransferEdit()'s rows as a text table.
std::string transferEditTable(const std::vector<TransferEditTime>& rows);

} // namespace texsplat::bench
