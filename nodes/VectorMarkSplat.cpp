#include "nodes/VectorMarkSplat.h"

#include "nodes/VolumeData.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/render/Frame.h"
#include "nodes/render/ScreenMarks.h"
#include "octree/ClassifiedGrid.h"
#include "octree/MarkSource.h"
#include "octree/VoxelShadows.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/fields/ValueFormat.h"

#include <cmath>
#include <string>

namespace texsplat::nodes {
namespace {

std::string dimsText(const glm::i64vec3& dims) {
    return std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
}

// Throws DataError unless `field` is finite and in (0, high].
void checkPositive(const sg::SFFloat& field, float high) {
    const float value = field.value();
    if (!std::isfinite(value) || !(value > 0.0f) || value > high) {
        throw DataError(field.name() + " must be finite and in (0, " + sg::formatFloat(high) +
                        "], got " + field.valueText());
    }
}

} // namespace

VectorMarkSplat::VectorMarkSplat() {
    const render::MarkDrawing marks;
    addField(textureOperator, "operator", render::MarkOperator::Modulate, kMarkOperatorNames,
             "The marks' colour: MODULATE the splat's own, BLEND from it at the tail to "
             "blendColor at the head");
    addField(blendColor, "blendColor", glm::vec3(1.0f),
             "The colour operator BLEND mixes the marks towards (the paper's C_const)");
    addField(phase, "phase", 0.0f,
             "Animation phase in life cycles of the marks; connect it to an ElapsedTime");
    addField(markType, "markType", marks.type, kMarkTypeNames,
             "Shape of the marks: SCRATCHES (streaks) or PARTICLES (comets), both brighter "
             "downstream");
    addField(markDensity, "markDensity", 0.6f,
             "How much of the image the marks cover (their area over the image area under the "
             "data), above 0 up to 4");
    addField(markLength, "markLength", marks.length,
             "Length of a voxel's marks in voxels (at least 20 pixels on screen), up to 64");
    addField(markWidth, "markWidth", marks.width,
             "Width of a voxel's marks in voxels (at least 5 pixels on screen), up to 8");
    addField(seed, "seed", 1, "Seed of the random marks: the same seed draws the same image");
    addField(maskData, "maskData", std::shared_ptr<sg::Node>(),
             "A scalar VolumeData of the same dimensions whose values choose where marks draw; "
             "NULL: everywhere");
    addField(maskRange, "maskRange", glm::vec2(0.0f, 1.0f),
             "Mask values that draw marks, inclusive (with maskData)");
}

VectorMarkSplat::~VectorMarkSplat() = default;

double VectorMarkSplat::markReach() const {
    return std::sqrt(3.0) / 2.0 + markLength.value() + 0.5 * markWidth.value();
}

void VectorMarkSplat::checkFields() const {
    ScalarSplat::checkFields();
    checkPositive(markDensity, kMaxMarkDensity);
    checkPositive(markLength, kMaxMarkLength);
    checkPositive(markWidth, kMaxMarkWidth);
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

const std::vector<octree::SplatMark>*
VectorMarkSplat::frameMarks(const std::shared_ptr<const octree::ClassifiedGrid>& classified,
                            render::FrameSplats& batch, int width, int height) {
    // A brick's marks are those of the whole grid's cells it holds (octree::MarkSource): the
    // bricks together draw the one-process marks.
    const glm::u64vec3 offset = mWhole ? mWhole->offset : glm::u64vec3(0);
    if (mMarks.of.lock() != classified || mMarks.offset != offset) {
        mMarks.shadows = std::make_shared<const octree::VoxelShadows>(*classified);
        mMarks.source = std::make_shared<const octree::MarkSource>(classified, offset);
        mMarks.of = classified;
        mMarks.offset = offset;
        mMarks.marksPerVoxel = -1.0;
    }
    // How deep the data is behind a pixel, seen from here towards the grid's centre, and how
    // large a voxel's mark is on screen there: marks per voxel = coverage / (area · depth).
    const glm::dvec3 centre =
        mWhole ? mWhole->centre : classified->toWorld((glm::dvec3(classified->dims()) - 1.0) * 0.5);
    const render::SplatView& view = batch.view;
    const glm::dvec3 sight =
        view.isPerspective ? centre - glm::dvec3(view.eye) : glm::dvec3(view.direction);
    const double depth = (mWhole ? *mWhole->shadows : *mMarks.shadows).meanDepth(sight);
    const float pixels = render::pixelsPerVoxel(batch, width, height, glm::vec3(centre));
    // The box the marks are cut to, its corners in either order (a flipped axis has a negative
    // spacing); a brick's is the whole volume's, not its own.
    const glm::vec3 first = mWhole ? mWhole->low : glm::vec3(classified->toWorld(glm::dvec3(-0.5)));
    const glm::vec3 last =
        mWhole ? mWhole->high
               : glm::vec3(classified->toWorld(glm::dvec3(classified->dims()) - 0.5));
    batch.marks.dataLow = glm::min(first, last);
    batch.marks.dataHigh = glm::max(first, last);
    batch.marks.marksPerVoxel = 0.0;
    if (depth > 0.0 && pixels > 0.0f && std::isfinite(pixels)) {
        const double area = render::markArea(batch.marks, pixels);
        batch.marks.marksPerVoxel = double(markDensity.value()) / (area * depth);
    }
    const auto seedValue = static_cast<std::uint32_t>(seed.value());
    if (mMarks.seed == seedValue && mMarks.marksPerVoxel == batch.marks.marksPerVoxel) {
        return &mMarks.marks; // the marks of the last frame
    }
    const double count =
        std::round(batch.marks.marksPerVoxel * static_cast<double>(mMarks.source->voxels()));
    const auto tooMany = [&](double marks) {
        return DataError(detail::nodeContext(*this) + ": " + sg::formatFloat(float(marks)) +
                         " marks are more than a splat list holds (" +
                         std::to_string(octree::SplatList::kMaxMarks) + "); lower markDensity");
    };
    if (count > static_cast<double>(octree::SplatList::kMaxMarks)) {
        throw tooMany(count);
    }
    // Each mark is held here, in the frame's list (with a splat of its own in a VectorSplat's)
    // and as the renderer places it on screen. The count drawn is about `count`: a few more are
    // let through the check.
    constexpr std::uint64_t kBytesPerMark = 2 * sizeof(octree::SplatMark) + sizeof(octree::Splat) +
                                            sizeof(std::uint32_t) + sizeof(render::ScreenMark);
    const auto marks = static_cast<std::uint64_t>(count);
    checkMemory(detail::nodeContext(*this) + ": drawing " + std::to_string(marks) +
                    " vector marks",
                byteProduct(marks, kBytesPerMark),
                "lower markDensity, render a smaller image, or give a larger --memory-limit");
    withMemoryStage("drawing vector marks", byteProduct(marks, kBytesPerMark),
                    "lower markDensity or render a smaller image", [&] {
                        mMarks.source->drawMarks(seedValue, batch.marks.marksPerVoxel,
                                                 mMarks.marks);
                    });
    if (mMarks.marks.size() > octree::SplatList::kMaxMarks) {
        const auto drawn = static_cast<double>(mMarks.marks.size());
        mMarks.marks.clear();
        mMarks.marksPerVoxel = -1.0;
        throw tooMany(drawn);
    }
    mMarks.seed = seedValue;
    mMarks.marksPerVoxel = batch.marks.marksPerVoxel;
    return &mMarks.marks;
}

render::MarkDrawing VectorMarkSplat::markDrawing() const {
    render::MarkDrawing marks;
    marks.type = markType.as<render::MarkType>();
    marks.textureOperator = textureOperator.as<render::MarkOperator>();
    marks.blendColor = blendColor.value();
    marks.phase = phase.value();
    marks.length = markLength.value();
    marks.width = markWidth.value();
    return marks;
}

bool VectorMarkSplat::isDrawingField(const sg::Field* field) const {
    // markLength and markWidth shape the footprint (its reach): not here.
    return ScalarSplat::isDrawingField(field) || field == &textureOperator ||
           field == &blendColor || field == &phase || field == &markType || field == &markDensity ||
           field == &seed || isClassificationField(field);
}

bool VectorMarkSplat::isClassificationField(const sg::Field* field) const {
    return field == &maskData || field == &maskRange;
}

} // namespace texsplat::nodes
