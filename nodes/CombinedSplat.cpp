#include "nodes/CombinedSplat.h"

#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/SplatFootprint.h"
#include "nodes/render/detail/ClassificationCache.h"
#include "scenegraph/Error.h"

#include <cmath>

namespace texsplat::nodes {

CombinedSplat::CombinedSplat() {
    addField(kernel, "kernel", SplatKernel::Paper, kSplatKernelNames,
             "Kernel of the scalar footprint under the marks: PAPER or GAUSSIAN, as in "
             "TextureSplat");
    addField(textureResolution, "textureResolution", 64,
             "Texels per side of the scalar footprint texture, 2 to 8192");
    addField(markContrast, "markContrast", 1.0f,
             "How strongly the marks show over the scalar splats, 0 (not at all) to 1");
    // Figure 7: vectors in a constant colour over the volume rendering.
    textureOperator.setValue(render::MarkOperator::Blend);
    textureOperator.setDefault(true);
}

void CombinedSplat::checkFields() const {
    VectorMarkSplat::checkFields();
    const float contrast = markContrast.value();
    if (!std::isfinite(contrast) || contrast < 0.0f || contrast > 1.0f) {
        throw DataError("markContrast must be in [0, 1], got " + markContrast.valueText());
    }
}

render::SplatFootprint CombinedSplat::makeFootprint() const {
    // The scalar part is a TextureSplat's, kernel and all (the CPU backend draws it alike).
    render::SplatFootprint result = TextureSplat::squareFootprint(
        kernel.as<SplatKernel>(), textureResolution.value(), size.value());
    result.shape = render::SplatShape::CombinedMarks;
    result.markReach = markReach();
    return result;
}

std::shared_ptr<const octree::ClassifiedGrid>
CombinedSplat::classify(render::detail::ClassificationCache& cache, sg::State& /*state*/,
                        const VolumeData& volume, const TransferFunction& transfer,
                        const glm::mat4& /*model*/) const {
    const volume::VectorGridPtr vectors = vectorGrid(volume);
    const volume::ScalarGridPtr scalars = volume.scalarGrid();
    const volume::ScalarGridPtr mask = companionGrid(maskData, vectors->geometry());
    render::detail::ClassificationInputs inputs;
    inputs.grids = {scalars, vectors, mask};
    return cache.classified(inputs, transfer, [&] {
        std::shared_ptr<octree::ClassifiedGrid> classified = transfer.classify(*scalars);
        classified->enableVectors();
        // Voxels without a vector keep a zero one: they draw their scalar part only.
        vectors->forEachActive([&](const glm::i64vec3& index, const glm::vec3& vector) {
            if (!mask || (mask->isActive(index) && isInMask(mask->value(index)))) {
                classified->setVector(glm::u64vec3(index), vector);
            }
        });
        return std::shared_ptr<const octree::ClassifiedGrid>(std::move(classified));
    });
}

render::MarkDrawing CombinedSplat::markDrawing() const {
    render::MarkDrawing marks = VectorMarkSplat::markDrawing();
    marks.isCombined = true;
    marks.contrast = markContrast.value();
    return marks;
}

bool CombinedSplat::isDrawingField(const sg::Field* field) const {
    return VectorMarkSplat::isDrawingField(field) || field == &markContrast;
}

} // namespace texsplat::nodes
