#include "nodes/render/detail/ClassificationCache.h"

#include "nodes/TransferFunction.h"

namespace texsplat::render::detail {

ClassificationCache::~ClassificationCache() { observe(nullptr); }

std::shared_ptr<const octree::ClassifiedGrid>
ClassificationCache::classified(const volume::ScalarGridPtr& grid,
                                const nodes::TransferFunction& transfer) {
    ClassificationInputs inputs;
    inputs.grids.push_back(grid);
    return classified(inputs, transfer, [&]() -> std::shared_ptr<const octree::ClassifiedGrid> {
        if (mValueRanges && grid == mValueRangesGrid) {
            return transfer.classify(*grid, *mValueRanges, mProgress);
        }
        // The grid's first classification makes its value ranges in the same pass.
        mValueRanges.reset();
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
    if (!mClassified || inputs != mInputs || &transfer != mTransfer || mTransferChanged) {
        mOctree.reset();
        mClassified.reset();
        observe(&transfer);
        mClassified = classify();
        ++mBuilds.classifications;
        mInputs = inputs;
        mTransferChanged = false;
    }
    return mClassified;
}

void ClassificationCache::invalidate() {
    mOctree.reset();
    mClassified.reset();
}

const octree::Octree& ClassificationCache::octree() {
    if (!mOctree) {
        mOctree = std::make_unique<octree::Octree>(mClassified, mProgress);
        ++mBuilds.octrees;
    }
    return *mOctree;
}

void ClassificationCache::changed(sg::Notifier& /*subject*/, const sg::Field* /*source*/) {
    mTransferChanged = true;
}

void ClassificationCache::subjectDestroyed(sg::Notifier& /*subject*/) {
    mTransfer = nullptr;
    mTransferChanged = true;
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
    if (mTransfer) {
        const_cast<nodes::TransferFunction*>(mTransfer)->addObserver(*this);
    }
}

} // namespace texsplat::render::detail
