#include "nodes/render/cpu/detail/SamplerCache.h"

namespace texsplat::render::cpu::detail {

std::shared_ptr<const FootprintSampler>
SamplerCache::footprint(const std::shared_ptr<const SplatFootprint>& footprint) {
    return mFootprints.get(footprint, 0, [&] {
        return std::make_shared<const FootprintSampler>(*footprint);
    });
}

std::shared_ptr<const MarkPlanes> SamplerCache::marks(const SplatFootprint& footprint) {
    return mMarks.get(footprint.table, 0, [&] {
        return std::make_shared<const MarkPlanes>(*footprint.table);
    });
}

} // namespace texsplat::render::cpu::detail
