#include "nodes/VectorMarkSplat.h"

#include "nodes/VolumeData.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/kernel/VectorSplatTable.h"
#include "scenegraph/Error.h"
#include "scenegraph/fields/ValueFormat.h"

#include <cmath>
#include <string>

namespace texsplat::nodes {
namespace {

const sg::EnumNames kMarkTypeNames{{"PARTICLES", kernel::MarkType::Particles},
                                   {"SCRATCHES", kernel::MarkType::Scratches}};

std::string dimsText(const glm::i64vec3& dims) {
    return std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
}

} // namespace

VectorMarkSplat::VectorMarkSplat() {
    const kernel::VectorTableParameters table;
    addField(textureOperator, "operator", render::MarkOperator::Modulate, kMarkOperatorNames,
             "The paper's texture operator: MODULATE scales the colour by the marks, BLEND mixes "
             "in blendColor");
    addField(blendColor, "blendColor", glm::vec3(1.0f),
             "Colour of the marks with operator BLEND (the paper's C_const), linear RGB");
    addField(phase, "phase", 0.0f,
             "Animation phase in cycles of the table's rows; connect it to an ElapsedTime");
    addField(tableRows, "tableRows", table.rows,
             "Animation phases of the vector splat table, 1 to 256");
    addField(tableColumns, "tableColumns", table.columns,
             "Foreshortening levels of the vector splat table, 1 to 64");
    addField(markType, "markType", table.markType, kMarkTypeNames,
             "Shape of the marks: PARTICLES (dots) or SCRATCHES (streaks along the vector)");
    addField(markDensity, "markDensity", table.markDensity,
             "Marks per square voxel in the table's textures, above 0 up to 64");
    addField(windowScale, "windowScale", table.windowScale,
             "Width of the marks' window relative to the scalar splat, 1 to 4");
    addField(seed, "seed", static_cast<std::int32_t>(table.seed),
             "Seed of the random marks and rows: the same seed draws the same image");
    addField(maskData, "maskData", std::shared_ptr<sg::Node>(),
             "A scalar VolumeData of the same dimensions whose values choose where marks draw; "
             "NULL: everywhere");
    addField(maskRange, "maskRange", glm::vec2(0.0f, 1.0f),
             "Mask values that draw marks, inclusive (with maskData)");
}

VectorMarkSplat::~VectorMarkSplat() = default;

std::shared_ptr<const kernel::VectorSplatTable> VectorMarkSplat::table() const {
    const kernel::VectorTableParameters parameters = tableParameters();
    if (!mTable || mTable->parameters() != parameters) {
        mTable = detail::withNodeContext(
            *this, [&] { return kernel::VectorSplatTable::shared(parameters); });
    }
    return mTable;
}

kernel::VectorTableParameters VectorMarkSplat::tableParameters() const {
    kernel::VectorTableParameters table;
    table.rows = tableRows.value();
    table.columns = tableColumns.value();
    table.markType = markType.as<kernel::MarkType>();
    table.markDensity = markDensity.value();
    table.splatExtent = size.value();
    table.windowScale = windowScale.value();
    table.seed = static_cast<std::uint32_t>(seed.value());
    return table;
}

void VectorMarkSplat::checkFields() const {
    ScalarSplat::checkFields();
    // The fields the table names otherwise, by their names here.
    if (tableRows.value() < 1 || tableRows.value() > kernel::VectorSplatTable::kMaxRows) {
        throw DataError("tableRows must be in 1.." +
                        std::to_string(kernel::VectorSplatTable::kMaxRows) + ", got " +
                        tableRows.valueText());
    }
    if (tableColumns.value() < 1 || tableColumns.value() > kernel::VectorSplatTable::kMaxColumns) {
        throw DataError("tableColumns must be in 1.." +
                        std::to_string(kernel::VectorSplatTable::kMaxColumns) + ", got " +
                        tableColumns.valueText());
    }
    if (size.value() > kernel::VectorSplatTable::kMaxSplatExtent) {
        throw DataError("size must be at most " +
                        sg::formatFloat(kernel::VectorSplatTable::kMaxSplatExtent) +
                        " for vector splats, got " + size.valueText());
    }
    kernel::VectorSplatTable::checkParameters(tableParameters());
    if (!std::isfinite(phase.value())) {
        throw DataError("phase must be finite, got " + phase.valueText());
    }
    const glm::vec3 blend = blendColor.value();
    if (!std::isfinite(blend.r) || !std::isfinite(blend.g) || !std::isfinite(blend.b) ||
        glm::any(glm::lessThan(blend, glm::vec3(0.0f)))) {
        throw DataError("blendColor must be finite and not negative, got " +
                        blendColor.valueText());
    }
    const glm::vec2 range = maskRange.value();
    if (!std::isfinite(range.x) || !std::isfinite(range.y) || range.x > range.y) {
        throw DataError("maskRange must be finite with maskRange[0] <= maskRange[1], got " +
                        maskRange.valueText());
    }
    checkVolumeField(maskData);
}

volume::VectorGridPtr VectorMarkSplat::vectorGrid(const VolumeData& volume) const {
    volume::VectorGridPtr vectors = volume.vectorGrid();
    if (!vectors) {
        throw DataError(detail::nodeContext(volume) +
                        " holds scalars; vector splats need a vector field (a raw file with 3 "
                        "components, an OpenVDB vec3s grid, or TORNADO, JET_STREAM, AEROGEL)");
    }
    return vectors;
}

volume::ScalarGridPtr VectorMarkSplat::companionGrid(const sg::SFNode& field,
                                                     const volume::GridGeometry& geometry) const {
    const auto* volume = dynamic_cast<const VolumeData*>(field.value().get());
    if (!volume) {
        return nullptr;
    }
    volume::ScalarGridPtr grid = volume->scalarGrid();
    if (grid->geometry().dims() != geometry.dims()) {
        throw DataError(field.name() + " " + detail::nodeContext(*volume) + " has " +
                        dimsText(grid->geometry().dims()) + " voxels but the vectors have " +
                        dimsText(geometry.dims()));
    }
    return grid;
}

void VectorMarkSplat::checkVolumeField(const sg::SFNode& field) {
    if (field.value() && !dynamic_cast<const VolumeData*>(field.value().get())) {
        throw DataError(field.name() + " must be a VolumeData, got " + field.value()->typeName());
    }
}

bool VectorMarkSplat::isInMask(float value) const {
    const glm::vec2 range = maskRange.value();
    return value >= range.x && value <= range.y;
}

std::optional<octree::VectorEmission> VectorMarkSplat::vectorEmission() const {
    octree::VectorEmission emission;
    emission.rows = tableRows.value();
    emission.columns = tableColumns.value();
    emission.seed = static_cast<std::uint32_t>(seed.value());
    return emission;
}

render::MarkDrawing VectorMarkSplat::markDrawing() const {
    render::MarkDrawing marks;
    marks.textureOperator = textureOperator.as<render::MarkOperator>();
    marks.blendColor = blendColor.value();
    // The fraction of a cycle first: a huge phase must not overflow the row count.
    const double cycle = std::fmod(static_cast<double>(phase.value()), 1.0);
    marks.rowShift = static_cast<int>(std::lround(cycle * tableRows.value()));
    return marks;
}

bool VectorMarkSplat::isDrawingField(const sg::Field* field) const {
    return ScalarSplat::isDrawingField(field) || field == &textureOperator ||
           field == &blendColor || field == &phase || isClassificationField(field);
}

bool VectorMarkSplat::isClassificationField(const sg::Field* field) const {
    return field == &maskData || field == &maskRange;
}

} // namespace texsplat::nodes
