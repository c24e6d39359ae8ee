#pragma once

#include "nodes/render/SplatFootprint.h"
#include "nodes/render/cpu/SplatRaster.h"
#include "nodes/render/detail/KeptPerObject.h"

#include <memory>

namespace texsplat::render::cpu::detail {

/// The footprint samplers a CpuRenderer has laid out, one per SplatFootprint (a node's
/// description for its current fields), dropped when the footprint is gone.
class SamplerCache {
public:
    /// The sampler of `footprint` (which must carry a texture), laid out on first use.
    std::shared_ptr<const FootprintSampler>
    footprint(const std::shared_ptr<const SplatFootprint>& footprint);

private:
    render::detail::KeptPerObject<SplatFootprint, std::shared_ptr<const FootprintSampler>>
        mFootprints;
};

} // namespace texsplat::render::cpu::detail
