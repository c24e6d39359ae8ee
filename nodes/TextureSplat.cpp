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

std::shared_ptr<render::SplatBatch> TextureSplat::makeBatch() const {
    const texsplat::kernel::CubicKernel paper = texsplat::kernel::CubicKernel::paper();
    const double extent = size.value();
    if (kernel.as<SplatKernel>() == SplatKernel::Gaussian) {
        const texsplat::kernel::GaussianKernel gaussian =
            texsplat::kernel::KernelOptimizer().fitGaussian(paper.support()).kernel;
        return std::make_shared<render::SplatBatch>(render::SplatBatch::textured(
            texsplat::kernel::FootprintTexture(gaussian, textureResolution.value(), extent)));
    }
    return std::make_shared<render::SplatBatch>(render::SplatBatch::textured(
        texsplat::kernel::FootprintTexture(paper, textureResolution.value(), extent)));
}

} // namespace texsplat::nodes
