#include "nodes/render/detail/ClassificationCache.h"

#include "nodes/TransferFunction.h"

namespace texsplat::render::detail {

ClassificationCache::~ClassificationCache() { observe(nullptr); }

std::shared_ptr<const octree::ClassifiedGrid>
ClassificationCache::classified(const volume::ScalarGridPtr& grid,
                                const nodes::TransferFunction& transfer) {
    ClassificationInputs inputs;
    inputs.grids.push_back(grid);
    return classified(inputs, transfer, [&] { return transfer.classify(*grid); });
}

std::shared_ptr<const octree::ClassifiedGrid>
ClassificationCache::classified(const ClassificationInputs& inputs,
                                const nodes::TransferFunction& transfer, const Classify& classify) {
    if (!mClassified || inputs != mInputs || &transfer != mTransfer || mTransferChanged) {
        mOctree.reset();
        mClassified.reset();
        observe(&transfer);
        mClassified = classify();
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
        mOctree = std::make_unique<octree::Octree>(mClassified);
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
