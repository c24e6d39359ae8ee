#include "nodes/render/cpu/detail/SamplerCache.h"

namespace texsplat::render::cpu::detail {

std::shared_ptr<const FootprintSampler>
SamplerCache::footprint(const std::shared_ptr<const SplatFootprint>& footprint) {
    return mFootprints
        .get(footprint, 0,
             [&] {
                 return Laid{std::make_shared<const FootprintSampler>(*footprint), {}, nullptr};
             })
        .sampler;
}

std::shared_ptr<const FootprintStamps>
SamplerCache::stamps(const std::shared_ptr<const SplatFootprint>& footprint,
                     const SplatSetup& setup) {
    if (!setup.isAffine()) {
        return nullptr;
    }
    const std::shared_ptr<const FootprintSampler> sampler = this->footprint(footprint);
    Laid& laid = mFootprints.get(footprint, 0, [] { return Laid{}; });
    if (!laid.stamps || laid.geometry != setup.stampGeometry()) {
        laid.stamps = setup.stampsFor(*sampler);
        laid.geometry = setup.stampGeometry();
    }
    return laid.stamps;
}

} // namespace texsplat::render::cpu::detail
