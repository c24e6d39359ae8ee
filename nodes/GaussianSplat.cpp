#include "nodes/GaussianSplat.h"

#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/KernelOptimizer.h"
#include "nodes/kernel/FootprintTexture.h"
#include "nodes/render/SplatFootprint.h"
#include "scenegraph/Error.h"

#include <string>

namespace texsplat::nodes {

GaussianSplat::GaussianSplat() {
    addField(radialSamples, "radialSamples", 3,
             "Vertices along a radius of the polygonal Gaussian, the centre included, 2 to 64");
    addField(azimuthSamples, "azimuthSamples", 7,
             "Vertices around each ring of the polygonal Gaussian, 3 to 256");
}

namespace {

void checkRange(const sg::SFInt32& field, int low, int high) {
    if (field.value() < low || field.value() > high) {
        throw DataError(field.name() + " must be " + std::to_string(low) + " to " +
                        std::to_string(high) + ", got " + field.valueText());
    }
}

} // namespace

void GaussianSplat::checkFields() const {
    ScalarSplat::checkFields();
    checkRange(radialSamples, kMinRadialSamples, kMaxRadialSamples);
    checkRange(azimuthSamples, kMinAzimuthSamples, kMaxAzimuthSamples);
}

render::SplatFootprint GaussianSplat::makeFootprint() const {
    // The fan's edges, where its interpolation bends, to 1/128 of the extent for the CPU backend.
    constexpr int kFanTextureResolution = 256;
    auto gaussian = std::make_shared<const kernel::GaussianKernel>(
        kernel::KernelOptimizer().fitGaussian(kernel::CubicKernel::paper().support()).kernel);
    render::SplatFootprint result;
    result.shape = render::SplatShape::GouraudPolygon;
    result.extent = size.value();
    result.radialSamples = radialSamples.value();
    result.azimuthSamples = azimuthSamples.value();
    result.texture = std::make_shared<const kernel::FootprintTexture>(
        kernel::FootprintTexture::gouraudFan(*gaussian, result.extent, result.radialSamples,
                                             result.azimuthSamples, kFanTextureResolution));
    result.kernel = std::move(gaussian);
    return result;
}

} // namespace texsplat::nodes
