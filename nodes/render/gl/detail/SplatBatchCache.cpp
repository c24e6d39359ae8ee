#include "nodes/render/gl/detail/SplatBatchCache.h"

#include "nodes/render/gl/SplatBatch.h"

#include <algorithm>

namespace texsplat::render::detail {

SplatBatchCache::SplatBatchCache() = default;
SplatBatchCache::~SplatBatchCache() = default;

SplatBatch& SplatBatchCache::batch(const std::shared_ptr<const SplatFootprint>& footprint,
                                   std::uint64_t context) {
    mEntries.erase(std::remove_if(mEntries.begin(), mEntries.end(),
                                  [](const Entry& entry) { return entry.key.expired(); }),
                   mEntries.end());
    for (const Entry& entry : mEntries) {
        if (entry.context == context && entry.key.lock() == footprint) {
            return *entry.batch;
        }
    }
    mEntries.push_back(
        {footprint, context, std::make_unique<SplatBatch>(SplatBatch::create(*footprint))});
    ++mMade;
    return *mEntries.back().batch;
}

} // namespace texsplat::render::detail
