#include "nodes/render/gl/detail/SplatBatchCache.h"

#include "nodes/render/gl/SplatBatch.h"

namespace texsplat::render::detail {

SplatBatchCache::SplatBatchCache() = default;
SplatBatchCache::~SplatBatchCache() = default;

SplatBatch& SplatBatchCache::batch(const std::shared_ptr<const SplatFootprint>& footprint,
                                   std::uint64_t context) {
    return *mBatches.get(footprint, context, [&] {
        return std::make_unique<SplatBatch>(SplatBatch::create(*footprint));
    });
}

} // namespace texsplat::render::detail
