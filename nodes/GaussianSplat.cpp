#include "nodes/GaussianSplat.h"

#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/KernelOptimizer.h"
#include "nodes/render/SplatBatch.h"

namespace texsplat::nodes {

GaussianSplat::GaussianSplat() {
    addField(radialSamples, "radialSamples", 3);
    addField(azimuthSamples, "azimuthSamples", 7);
}

std::shared_ptr<render::SplatBatch> GaussianSplat::makeBatch() const {
    const kernel::GaussianKernel gaussian =
        kernel::KernelOptimizer().fitGaussian(kernel::CubicKernel::paper().support()).kernel;
    return std::make_shared<render::SplatBatch>(render::SplatBatch::polygonal(
        gaussian, size.value(), radialSamples.value(), azimuthSamples.value()));
}

} // namespace texsplat::nodes
