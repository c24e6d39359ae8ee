#include "nodes/render/detail/ClassificationCache.h"

#include "nodes/TransferFunction.h"
#include "nodes/volume/ValueHistogram.h"

namespace texsplat::render::detail {
namespace {

// What a scalar grid's classification reads besides the transfer function.
ClassificationInputs scalarInputs(const volume::ScalarGridPtr& grid) {
    ClassificationInputs inputs;
    inputs.grids.push_back(grid);
    return inputs;
}

} // namespace

ClassificationCache::~ClassificationCache() { observe(nullptr); }

std::shared_ptr<const octree::ClassifiedGrid>
ClassificationCache::classified(const volume::ScalarGridPtr& grid,
                                const nodes::TransferFunction& transfer) {
    const ClassificationInputs inputs = scalarInputs(grid);
    return classified(inputs, transfer, [&]() -> std::shared_ptr<const octree::ClassifiedGrid> {
        if (mValueRanges && grid == mValueRangesGrid) {
            return transfer.classify(*grid, *mValueRanges, mProgress);
        }
        // The grid's first classification makes its value ranges in the same pass.
        mValueRanges.reset();
        mHistograms.reset();
        auto ranges =
            std::make_unique<octree::ValueRanges>(glm::u64vec3(grid->geometry().dims()));
        std::shared_ptr<const octree::ClassifiedGrid> result =
            transfer.classifyRecording(*grid, *ranges, mProgress);
        mValueRanges = std::move(ranges);
        mValueRangesGrid = grid;
        ++mBuilds.valueRanges;
        return result;
    });
}

std::shared_ptr<const octree::ClassifiedGrid>
ClassificationCache::classified(const ClassificationInputs& inputs,
                                const nodes::TransferFunction& transfer, const Classify& classify) {
    if (!isCurrent(inputs, transfer)) {
        mOctree.reset();
        mClassified.reset();
        // A preview is drawn only while no classification by the function as it is exists.
        mPreviewOctree.reset();
        mPreview.reset();
        observe(&transfer);
        mClassified = classify();
        ++mBuilds.classifications;
        mInputs = inputs;
        mTransferChanged = false;
    }
    return mClassified;
}

std::shared_ptr<const octree::ClassifiedGrid>
ClassificationCache::preview(const volume::ScalarGridPtr& grid,
                             const nodes::TransferFunction& transfer) {
    const ClassificationInputs inputs = scalarInputs(grid);
    if (isCurrent(inputs, transfer) || !mValueRanges || grid != mValueRangesGrid) {
        return nullptr;
    }
    // Another function is observed from now on (which makes the preview stale); the
    // classification by an earlier function serves no frame any more.
    observe(&transfer);
    mOctree.reset();
    mClassified.reset();
    if (!mPreview || mPreviewStale) {
        mPreviewOctree.reset();
        mPreview.reset();
        if (!mHistograms) {
            // Once per grid, for its first edit previewed: one more walk over its blocks.
            mHistograms = std::make_unique<octree::ValueHistograms>(
                volume::blockValueHistograms(*grid, mProgress));
            ++mBuilds.valueHistograms;
        }
        mPreview = transfer.classifyBlockMeans(*grid, *mValueRanges, *mHistograms);
        mPreviewStale = false;
        ++mBuilds.previews;
    }
    return mPreview;
}

const octree::Octree& ClassificationCache::previewOctree() {
    if (!mPreviewOctree) {
        mPreviewOctree = std::make_unique<octree::Octree>(mPreview, mProgress);
    }
    return *mPreviewOctree;
}

bool ClassificationCache::isCurrent(const ClassificationInputs& inputs,
                                    const nodes::TransferFunction& transfer) const {
    return mClassified && inputs == mInputs && &transfer == mTransfer && !mTransferChanged;
}

void ClassificationCache::invalidate() {
    mOctree.reset();
    mClassified.reset();
    mPreviewOctree.reset();
    mPreview.reset();
}

const octree::Octree& ClassificationCache::octree() {
    if (!mOctree) {
        mOctree = std::make_unique<octree::Octree>(mClassified, mProgress);
        ++mBuilds.octrees;
    }
    return *mOctree;
}

void ClassificationCache::changed(sg::Notifier& /*subject*/, const sg::Field* source) {
    if (mTransfer && (mTransfer->isLabelField(source) || mTransfer->isShadingField(source))) {
        return; // a new title or lighting classifies nothing differently
    }
    mTransferChanged = true;
    mPreviewStale = true;
}

void ClassificationCache::subjectDestroyed(sg::Notifier& /*subject*/) {
    mTransfer = nullptr;
    mTransferChanged = true;
    mPreviewStale = true;
}

void ClassificationCache::observe(const nodes::TransferFunction* transfer) {
    if (transfer == mTransfer) {
        return;
    }
    // Observing does not change the transfer function; the state hands it out const.
    if (mTransfer) {
        const_cast<nodes::TransferFunction*>(mTransfer)->removeObserver(*this);
    }
    mTransfer = transfer;
    mPreviewStale = true; // edits of an unobserved function went unheard
    if (mTransfer) {
        const_cast<nodes::TransferFunction*>(mTransfer)->addObserver(*this);
    }
}

} // namespace texsplat::render::detail
