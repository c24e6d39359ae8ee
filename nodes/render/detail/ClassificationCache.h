#pragma once

#include "nodes/volume/Grid.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Octree.h"
#include "octree/ValueHistograms.h"
#include "octree/ValueRanges.h"
#include "scenegraph/Observer.h"
#include "scenegraph/WorkProgress.h"

#include <glm/mat4x4.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace texsplat::nodes {
class TransferFunction;
} // namespace texsplat::nodes

namespace texsplat::render::detail {

/// What a classification reads besides the transfer function: the grids (compared by identity;
/// VolumeData hands out a new grid when it reloads) and, for classifications that depend on
/// where the volume is (colour by position), the model matrix.
struct ClassificationInputs {
    std::vector<std::shared_ptr<const void>> grids;
    glm::mat4 model{1.0f};

    bool operator==(const ClassificationInputs& other) const {
        return grids == other.grids && model == other.model;
    }
    bool operator!=(const ClassificationInputs& other) const { return !(*this == other); }
};

/// A splat node's classified grid and octree, kept across frames ("cache classification and
/// the octree on the node"): rebuilt when the inputs differ from last time, when the transfer
/// function is replaced or changes (observed), or after invalidate(). A scalar grid's block value
/// ranges and histograms (octree::ValueRanges, octree::ValueHistograms) depend on the data alone:
/// made once per grid (the ranges with its first classification, the histograms for its first
/// preview), they survive every transfer-function change, let classification skip what the new
/// function hides, and give an interactive frame its preview of an edit.
class ClassificationCache final : public sg::Observer {
public:
    /// How many times each structure was made since the cache was: what a test of "a transfer
    /// function edit needs no new data hierarchy" counts.
    struct Builds {
        std::uint64_t valueRanges = 0;
        std::uint64_t classifications = 0;
        std::uint64_t octrees = 0;
        std::uint64_t valueHistograms = 0;
        std::uint64_t previews = 0;
    };

    /// Makes the classified grid from the inputs.
    using Classify = std::function<std::shared_ptr<const octree::ClassifiedGrid>()>;

    ClassificationCache() = default;
    ClassificationCache(const ClassificationCache&) = delete;
    ClassificationCache& operator=(const ClassificationCache&) = delete;
    ~ClassificationCache() override;

    /// The scalar `grid` classified by `transfer`, from the cache when still valid; a new
    /// classification tells the work progress how it goes (and may be cancelled by it).
    std::shared_ptr<const octree::ClassifiedGrid> classified(const volume::ScalarGridPtr& grid,
                                                             const nodes::TransferFunction& transfer);

    /// What `classify` makes of `inputs` and `transfer`, from the cache when still valid.
    std::shared_ptr<const octree::ClassifiedGrid> classified(const ClassificationInputs& inputs,
                                                             const nodes::TransferFunction& transfer,
                                                             const Classify& classify);

    /// The octree over the last classified() grid, built on first use (telling the work
    /// progress).
    const octree::Octree& octree();

    /// For an interactive frame right after `transfer` changed: the grid of `grid`'s block means
    /// under `transfer` (TransferFunction::classifyBlockMeans(), from the grid's block value
    /// histograms, made on the first call for a grid, reading no voxel after that), made once
    /// per version of the function; the classification by an earlier function is released. Null
    /// when there is nothing to preview: classified() holds `grid` classified by `transfer` as
    /// it is (draw that), or `grid` was never classified here.
    std::shared_ptr<const octree::ClassifiedGrid> preview(const volume::ScalarGridPtr& grid,
                                                          const nodes::TransferFunction& transfer);

    /// The octree over the last preview() grid, built on first use.
    const octree::Octree& previewOctree();

    /// Where the scalar classification and the octree build made from now on report, and may be
    /// cancelled (the action's, set by the splat node each frame).
    void setWorkProgress(sg::WorkProgress progress) { mProgress = std::move(progress); }

    /// Bytes of the grid's value ranges and histograms held (0 before a scalar grid was
    /// classified).
    std::uint64_t dataSummaryBytes() const {
        return (mValueRanges ? mValueRanges->memoryBytes() : 0) +
               (mHistograms ? mHistograms->memoryBytes() : 0);
    }

    /// What was made so far.
    const Builds& builds() const { return mBuilds; }

    /// Forgets the classification (the node's own fields that classification reads changed).
    void invalidate();

    void changed(sg::Notifier& subject, const sg::Field* source) override;
    void subjectDestroyed(sg::Notifier& subject) override;

private:
    // Whether the classification held is the one of `inputs` by `transfer` as it is now.
    bool isCurrent(const ClassificationInputs& inputs,
                   const nodes::TransferFunction& transfer) const;
    void observe(const nodes::TransferFunction* transfer);

    ClassificationInputs mInputs;
    const nodes::TransferFunction* mTransfer = nullptr;
    bool mTransferChanged = false;
    bool mPreviewStale = true; // the transfer function changed since the preview was made
    std::shared_ptr<const octree::ClassifiedGrid> mClassified;
    std::unique_ptr<octree::Octree> mOctree;
    volume::ScalarGridPtr mValueRangesGrid;
    std::unique_ptr<octree::ValueRanges> mValueRanges;
    std::unique_ptr<octree::ValueHistograms> mHistograms;
    std::shared_ptr<const octree::ClassifiedGrid> mPreview; // of mValueRangesGrid
    std::unique_ptr<octree::Octree> mPreviewOctree;
    Builds mBuilds;
    sg::WorkProgress mProgress;
};

} // namespace texsplat::render::detail
