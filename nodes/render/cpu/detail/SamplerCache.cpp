#include "nodes/render/cpu/detail/SamplerCache.h"

namespace texsplat::render::cpu::detail {

std::shared_ptr<const FootprintSampler>
SamplerCache::footprint(const std::shared_ptr<const SplatFootprint>& footprint) {
    return mFootprints.get(footprint, 0, [&] {
        return std::make_shared<const FootprintSampler>(*footprint);
    });
}

} // namespace texsplat::render::cpu::detail
