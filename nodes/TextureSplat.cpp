#include "nodes/TextureSplat.h"

#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/KernelOptimizer.h"
#include "nodes/render/SplatBatch.h"

namespace texsplat::nodes {

TextureSplat::TextureSplat() {
    addField(kernel, "kernel", SplatKernel::Paper, kSplatKernelNames);
    addField(textureResolution, "textureResolution", 64);
}

texsplat::kernel::FootprintTexture TextureSplat::footprint(SplatKernel splatKernel, int resolution,
                                                           double extent) {
    const texsplat::kernel::CubicKernel paper = texsplat::kernel::CubicKernel::paper();
    if (splatKernel == SplatKernel::Gaussian) {
        const texsplat::kernel::GaussianKernel gaussian =
            texsplat::kernel::KernelOptimizer().fitGaussian(paper.support()).kernel;
        return texsplat::kernel::FootprintTexture(gaussian, resolution, extent);
    }
    return texsplat::kernel::FootprintTexture(paper, resolution, extent);
}

std::shared_ptr<render::SplatBatch> TextureSplat::makeBatch() const {
    return std::make_shared<render::SplatBatch>(render::SplatBatch::textured(
        footprint(kernel.as<SplatKernel>(), textureResolution.value(), size.value())));
}

} // namespace texsplat::nodes
