#include "nodes/render/cpu/detail/SamplerCache.h"

#include <algorithm>

namespace texsplat::render::cpu::detail {
namespace {

// Drops the entries whose key is gone.
template <class Entry> void prune(std::vector<Entry>& entries) {
    entries.erase(std::remove_if(entries.begin(), entries.end(),
                                 [](const Entry& entry) { return entry.key.expired(); }),
                  entries.end());
}

} // namespace

std::shared_ptr<const FootprintSampler>
SamplerCache::footprint(const std::shared_ptr<const SplatFootprint>& footprint) {
    prune(mFootprints);
    for (const FootprintEntry& entry : mFootprints) {
        if (entry.key.lock() == footprint) {
            return entry.sampler;
        }
    }
    auto sampler = std::make_shared<const FootprintSampler>(*footprint);
    mFootprints.push_back({footprint, sampler});
    return sampler;
}

std::shared_ptr<const MarkPlanes> SamplerCache::marks(const SplatFootprint& footprint) {
    prune(mMarks);
    for (const MarkEntry& entry : mMarks) {
        if (entry.key.lock() == footprint.table) {
            return entry.planes;
        }
    }
    auto planes = std::make_shared<const MarkPlanes>(*footprint.table);
    mMarks.push_back({footprint.table, planes});
    return planes;
}

} // namespace texsplat::render::cpu::detail
