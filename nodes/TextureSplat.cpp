#include "nodes/TextureSplat.h"

#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/KernelOptimizer.h"
#include "nodes/render/SplatFootprint.h"

namespace texsplat::nodes {

TextureSplat::TextureSplat() {
    addField(kernel, "kernel", SplatKernel::Paper, kSplatKernelNames,
             "Kernel whose footprint the texture holds: PAPER's cubic, or the GAUSSIAN fitted to "
             "its support");
    addField(textureResolution, "textureResolution", 64,
             "Texels per side of the footprint texture, 2 to 8192");
}

std::shared_ptr<const texsplat::kernel::RadialKernel>
TextureSplat::radialKernel(SplatKernel splatKernel) {
    const texsplat::kernel::CubicKernel paper = texsplat::kernel::CubicKernel::paper();
    if (splatKernel == SplatKernel::Gaussian) {
        return std::make_shared<const texsplat::kernel::GaussianKernel>(
            texsplat::kernel::KernelOptimizer().fitGaussian(paper.support()).kernel);
    }
    return std::make_shared<const texsplat::kernel::CubicKernel>(paper);
}

texsplat::kernel::FootprintTexture TextureSplat::footprint(SplatKernel splatKernel, int resolution,
                                                           double extent) {
    return texsplat::kernel::FootprintTexture(*radialKernel(splatKernel), resolution, extent);
}

render::SplatFootprint TextureSplat::makeFootprint() const {
    render::SplatFootprint result;
    result.shape = render::SplatShape::TexturedSquare;
    result.extent = size.value();
    result.kernel = radialKernel(kernel.as<SplatKernel>());
    result.texture = std::make_shared<const texsplat::kernel::FootprintTexture>(
        *result.kernel, textureResolution.value(), size.value());
    return result;
}

} // namespace texsplat::nodes
