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

render::SplatFootprint TextureSplat::squareFootprint(SplatKernel splatKernel, int resolution,
                                                     float extent) {
    render::SplatFootprint result;
    result.shape = render::SplatShape::TexturedSquare;
    result.extent = extent;
    result.kernel = radialKernel(splatKernel);
    result.texture = std::make_shared<const texsplat::kernel::FootprintTexture>(*result.kernel,
                                                                                resolution, extent);
    return result;
}

render::SplatFootprint TextureSplat::makeFootprint() const {
    return squareFootprint(kernel.as<SplatKernel>(), textureResolution.value(), size.value());
}

} // namespace texsplat::nodes
