#pragma once

#include "nodes/volume/Grid.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Octree.h"
#include "scenegraph/Observer.h"

#include <memory>

namespace texsplat::nodes {
class TransferFunction;
} // namespace texsplat::nodes

namespace texsplat::render::detail {

/// A splat node's classified grid and octree, kept across frames ("cache classification and
/// the octree on the node"): rebuilt when the volume hands out a different grid (VolumeData
/// replaces its grid when one of its fields changes) or when the transfer function is replaced
/// or changes (observed).
class ClassificationCache final : public sg::Observer {
public:
    ClassificationCache() = default;
    ClassificationCache(const ClassificationCache&) = delete;
    ClassificationCache& operator=(const ClassificationCache&) = delete;
    ~ClassificationCache() override;

    /// Whether classified() would classify again for these inputs.
    bool isStale(const volume::ScalarGridPtr& grid, const nodes::TransferFunction& transfer) const;

    /// The grid classified by `transfer`, from the cache when still valid.
    std::shared_ptr<const octree::ClassifiedGrid> classified(const volume::ScalarGridPtr& grid,
                                                             const nodes::TransferFunction& transfer);

    /// The octree over the last classified() grid, built on first use.
    const octree::Octree& octree();

    void changed(sg::Notifier& subject, const sg::Field* source) override;
    void subjectDestroyed(sg::Notifier& subject) override;

private:
    void observe(const nodes::TransferFunction* transfer);

    volume::ScalarGridPtr mGrid;
    const nodes::TransferFunction* mTransfer = nullptr;
    bool mTransferChanged = false;
    std::shared_ptr<const octree::ClassifiedGrid> mClassified;
    std::unique_ptr<octree::Octree> mOctree;
};

} // namespace texsplat::render::detail
