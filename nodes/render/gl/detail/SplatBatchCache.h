#pragma once

#include "nodes/render/SplatFootprint.h"
#include "nodes/render/detail/KeptPerObject.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::render {
class SplatBatch;
} // namespace texsplat::render

namespace texsplat::render::detail {

/// The SplatBatches a GlRenderer has made, one per SplatFootprint (a node's description for its
/// current fields) and GL context, dropped when the footprint is gone.
class SplatBatchCache {
public:
    SplatBatchCache();
    ~SplatBatchCache();

    /// The batch drawing `footprint` in the context of serial `context`, made on first use.
    SplatBatch& batch(const std::shared_ptr<const SplatFootprint>& footprint,
                      std::uint64_t context);

    /// Batches made so far.
    std::size_t made() const { return mBatches.made(); }

private:
    KeptPerObject<SplatFootprint, std::unique_ptr<SplatBatch>> mBatches;
};

} // namespace texsplat::render::detail
