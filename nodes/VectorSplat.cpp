#include "nodes/VectorSplat.h"

#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/detail/ColorText.h"
#include "nodes/render/SplatFootprint.h"
#include "nodes/render/detail/ClassificationCache.h"
#include "scenegraph/Error.h"

#include <cmath>

namespace texsplat::nodes {

VectorSplat::VectorSplat() {
    addField(colorMode, "colorMode", VectorColorMode::Magnitude, kVectorColorModeNames,
             "Colour of the marks through the colour map: MAGNITUDE |v|, SCALAR colorData, "
             "POSITION a coordinate; CONSTANT: color");
    addField(colorData, "colorData", std::shared_ptr<sg::Node>(),
             "The scalar VolumeData (same dimensions) that colorMode SCALAR colours by");
    addField(positionAxis, "positionAxis", Axis::Z, kAxisNames,
             "World axis whose coordinate colorMode POSITION colours by (e.g. Z for altitude)");
    addField(positionRange, "positionRange", glm::vec2(0.0f, 1.0f),
             "World coordinates mapped onto the TransferFunction's range by colorMode POSITION");
    addField(color, "color", glm::vec3(1.0f), "Colour of colorMode CONSTANT");
}

void VectorSplat::checkFields() const {
    VectorMarkSplat::checkFields();
    if (!detail::isFiniteColor(color.value()) ||
        glm::any(glm::lessThan(color.value(), glm::vec3(0.0f)))) {
        throw DataError("color must be finite and not negative, got " +
                        detail::formatColor(color.value()));
    }
    const glm::vec2 range = positionRange.value();
    if (!std::isfinite(range.x) || !std::isfinite(range.y) || !(range.x < range.y)) {
        throw DataError("positionRange must be finite with positionRange[0] < positionRange[1], "
                        "got " + positionRange.valueText());
    }
    checkVolumeField(colorData);
    if (colorMode.as<VectorColorMode>() == VectorColorMode::Scalar && !colorData.value()) {
        throw DataError("colorMode SCALAR needs colorData, a scalar VolumeData");
    }
}

render::SplatFootprint VectorSplat::makeFootprint() const {
    render::SplatFootprint result;
    result.shape = render::SplatShape::VectorMarks;
    result.markReach = markReach();
    result.extent = result.markReach;
    return result;
}

std::shared_ptr<const octree::ClassifiedGrid>
VectorSplat::classify(render::detail::ClassificationCache& cache, sg::State& /*state*/,
                      const VolumeData& volume, const TransferFunction& transfer,
                      const glm::mat4& model) const {
    const volume::VectorGridPtr vectors = vectorGrid(volume);
    const volume::GridGeometry& geometry = vectors->geometry();
    const auto mode = colorMode.as<VectorColorMode>();
    const volume::ScalarGridPtr mask = companionGrid(maskData, geometry);
    const volume::ScalarGridPtr colors =
        mode == VectorColorMode::Scalar ? companionGrid(colorData, geometry) : nullptr;
    render::detail::ClassificationInputs inputs;
    inputs.grids = {vectors, mask, colors};
    if (mode == VectorColorMode::Position) {
        inputs.model = model;
    }
    return cache.classified(inputs, transfer, [&] {
        auto classified = std::make_shared<octree::ClassifiedGrid>(
            glm::u64vec3(geometry.dims()), geometry.spacing(), geometry.origin());
        classified->enableVectors();
        const int axis = static_cast<int>(positionAxis.as<Axis>());
        const glm::vec2 coordinates = positionRange.value();
        const DataScale scale = transfer.dataScale(*vectors);
        // colorMode SCALAR colours the other grid's values over that grid's own range.
        const DataScale colorScale = colors ? transfer.dataScale(*colors) : scale;
        const glm::vec2 values = scale.range;
        vectors->forEachActive([&](const glm::i64vec3& index, const glm::vec3& vector) {
            // In double: a huge vector's squared length overflows float.
            const double magnitude = glm::length(glm::dvec3(vector));
            if (!(magnitude > 0.0)) {
                return; // no direction: no marks
            }
            if (mask && !(mask->isActive(index) && isInMask(mask->value(index)))) {
                return;
            }
            const Classification medium = transfer.classify(static_cast<float>(magnitude), scale);
            if (!(medium.extinction > 0.0f)) {
                return;
            }
            glm::vec3 polygon = color.value();
            switch (mode) {
            case VectorColorMode::Magnitude:
                polygon = transfer.color(static_cast<float>(magnitude), scale);
                break;
            case VectorColorMode::Scalar:
                polygon = colors->isActive(index) ? transfer.color(colors->value(index), colorScale)
                                                  : glm::vec3(0.0f);
                break;
            case VectorColorMode::Position: {
                const glm::vec4 world =
                    model * glm::vec4(glm::vec3(geometry.indexToWorld(glm::dvec3(index))), 1.0f);
                const float t = (world[axis] - coordinates.x) / (coordinates.y - coordinates.x);
                polygon = transfer.color(values.x + t * (values.y - values.x), scale);
                break;
            }
            case VectorColorMode::Constant:
                break;
            }
            classified->setVoxel(glm::u64vec3(index), polygon, medium.extinction);
            classified->setVector(glm::u64vec3(index), vector);
        });
        return classified;
    });
}

bool VectorSplat::isClassificationField(const sg::Field* field) const {
    return VectorMarkSplat::isClassificationField(field) || field == &colorMode ||
           field == &colorData || field == &positionAxis || field == &positionRange ||
           field == &color;
}

} // namespace texsplat::nodes
