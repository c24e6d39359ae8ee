#pragma once

#include "nodes/render/SplatFootprint.h"
#include "nodes/render/cpu/FootprintStamps.h"
#include "nodes/render/cpu/SplatRaster.h"
#include "nodes/render/detail/KeptPerObject.h"

#include <memory>

namespace texsplat::render::cpu::detail {

/// The footprint samplers a CpuRenderer has laid out, one per SplatFootprint (a node's
/// description for its current fields), dropped when the footprint is gone; and each one's
/// stamps for the last view that stamped it, so that a frame after frame of an orthographic
/// view that keeps its scale and direction tabulates them once.
class SamplerCache {
public:
    /// The sampler of `footprint` (which must carry a texture), laid out on first use.
    std::shared_ptr<const FootprintSampler>
    footprint(const std::shared_ptr<const SplatFootprint>& footprint);

    /// The stamps of `footprint`'s sampler for `setup`'s view (SplatSetup::stampsFor()), or
    /// null where they do not apply.
    std::shared_ptr<const FootprintStamps>
    stamps(const std::shared_ptr<const SplatFootprint>& footprint, const SplatSetup& setup);

private:
    struct Laid {
        std::shared_ptr<const FootprintSampler> sampler;
        StampGeometry geometry;                        // what `stamps` are for
        std::shared_ptr<const FootprintStamps> stamps; // null: none made yet
    };
    render::detail::KeptPerObject<SplatFootprint, Laid> mFootprints;
};

} // namespace texsplat::render::cpu::detail
