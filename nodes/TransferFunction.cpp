#include "nodes/TransferFunction.h"

#include "nodes/colormap/ParaViewColorMap.h"
#include "nodes/detail/ColorText.h"
#include "nodes/detail/DataRange.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/detail/TransferTable.h"
#include "nodes/elements/TransferFunctionElement.h"
#include "nodes/volume/BlockBatches.h"
#include "octree/ValueHistograms.h"
#include "octree/ValueRanges.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/fields/ValueFormat.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace texsplat::nodes {

TransferFunction::TransferFunction() {
    addField(preset, "preset", ColorPreset::Gray, kColorPresetNames,
             "Named colour map, used when colors and colorMapFile are empty");
    addField(colorMapFile, "colorMapFile", std::string(),
             "A ParaView colour-map JSON file (relative to the scene file's folder); replaces "
             "preset");
    addField(colorValues, "colorValues", std::vector<float>{},
             "Positions of colors in the range normalized to 0..1, non-decreasing");
    addField(colors, "colors", std::vector<glm::vec3>{},
             "Colour control points, RGB 0..1 as colour maps give them (display values), one "
             "per colorValues; replace the colour map");
    addField(opacityValues, "opacityValues", std::vector<float>{0.0f, 1.0f},
             "Positions of opacities in the range normalized to 0..1, non-decreasing");
    addField(opacities, "opacities", std::vector<float>{0.0f, 1.0f},
             "Extinction control points: opacity per unitDistance of world length, >= 0");
    addField(range, "range", glm::vec2(0.0f, 1.0f),
             "Data values mapped to 0 and 1 with rangeMode FIXED (or AUTO once written)");
    addField(rangeMode, "rangeMode", RangeMode::Auto, kRangeModeNames,
             "Where the range comes from: FIXED range, DATA min/max, PERCENTILE, or AUTO (FIXED "
             "when range is written, else DATA)");
    addField(percentiles, "percentiles", glm::vec2(1.0f, 99.0f),
             "Lower and upper percentile of the data (0..100) that rangeMode PERCENTILE maps to "
             "0 and 1");
    addField(unitDistance, "unitDistance", 1.0f,
             "World length over which opacities and emission apply; 0: one voxel of the data");
    addField(emission, "emission", 0.0f,
             "Glow that does not absorb: emission is colour times (opacity + emission), >= 0");
    addField(title, "title", std::string(),
             "What the values are (\"Temperature\"): the colour bar's title; not used to classify");
    addField(units, "units", std::string(),
             "The values' unit (\"K\"): the colour bar shows \"title (units)\"");
    addField(shade, "shade", false,
             "Light the medium by the gradient of its extinction, as VTK's ShadeOn: surfaces "
             "inside the volume show their shape");
    addField(ambient, "ambient", 0.1f, "With shade: the part of the colour shown unlit, >= 0");
    addField(diffuse, "diffuse", 0.7f,
             "With shade: the part lit by |n.l| of each light (Lambert), >= 0");
    addField(specular, "specular", 0.2f,
             "With shade: the highlight |n.h|^specularPower of each light, in the light's "
             "colour, >= 0");
    addField(specularPower, "specularPower", 10.0f,
             "With shade: the highlight's sharpness (Phong exponent), > 0");
}

glm::vec4 TransferFunction::shadingCoefficients() const {
    const std::string context = detail::nodeContext(*this);
    for (const sg::SFFloat* field : {&ambient, &diffuse, &specular}) {
        if (!std::isfinite(field->value()) || field->value() < 0.0f) {
            throw DataError(context + ": " + field->name() + " must be finite and >= 0, got " +
                            field->valueText());
        }
    }
    if (!std::isfinite(specularPower.value()) || !(specularPower.value() > 0.0f)) {
        throw DataError(context + ": specularPower must be finite and > 0, got " +
                        specularPower.valueText());
    }
    return {ambient.value(), diffuse.value(), specular.value(), specularPower.value()};
}

namespace {

std::string element(const sg::Field& field, std::size_t index) {
    return field.name() + "[" + std::to_string(index) + "]";
}

// Checks a pair of control-point fields and returns them as one piecewise-linear map.
template <class Y, class Field, class CheckValue>
detail::PiecewiseLinear<Y> controlPoints(const std::string& context, const sg::MFFloat& positions,
                                         const Field& values, CheckValue checkValue) {
    if (positions.size() != values.size()) {
        throw DataError(context + ": " + positions.name() + " has " +
                        std::to_string(positions.size()) + " values but " + values.name() +
                        " has " + std::to_string(values.size()));
    }
    if (positions.isEmpty()) {
        throw DataError(context + ": " + positions.name() + " and " + values.name() +
                        " are empty; give at least one control point");
    }
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const float x = positions[i];
        if (!std::isfinite(x)) {
            throw DataError(context + ": " + element(positions, i) + " must be finite, got " +
                            sg::formatFloat(x));
        }
        if (i > 0 && x < positions[i - 1]) {
            throw DataError(context + ": " + positions.name() + " must not decrease, but " +
                            element(positions, i) + " = " + sg::formatFloat(x) + " follows " +
                            sg::formatFloat(positions[i - 1]));
        }
        checkValue(i);
    }
    return {positions.values(), values.values()};
}

} // namespace

std::shared_ptr<const detail::TransferTable> TransferFunction::buildTable() const {
    const std::string context = detail::nodeContext(*this);
    auto table = std::make_shared<detail::TransferTable>();

    const glm::vec2 bounds = range.value();
    if (!std::isfinite(bounds.x) || !std::isfinite(bounds.y) || !(bounds.x < bounds.y)) {
        throw DataError(context + ": range must be finite with range[0] < range[1], got " +
                        range.valueText());
    }
    table->rangeMin = bounds.x;
    table->rangeMax = bounds.y;
    RangeMode mode = rangeMode.as<RangeMode>();
    if (mode == RangeMode::Auto) {
        // A connected range is given too, though its value leaves the default flag alone.
        mode = range.isDefault() && !range.isConnected() ? RangeMode::Data : RangeMode::Fixed;
    }
    table->rangeMode = static_cast<int>(mode);
    const glm::vec2 percent = percentiles.value();
    if (!(percent.x >= 0.0f && percent.x < percent.y && percent.y <= 100.0f)) {
        throw DataError(context + ": percentiles must satisfy 0 <= percentiles[0] < "
                                  "percentiles[1] <= 100, got " +
                        percentiles.valueText());
    }
    table->percentiles = glm::dvec2(percent);
    const float unit = unitDistance.value();
    if (!std::isfinite(unit) || unit < 0.0f) {
        throw DataError(context + ": unitDistance must be finite and >= 0 (0: one voxel), got " +
                        sg::formatFloat(unit));
    }
    table->unitDistance = unit;

    if (colorValues.isEmpty() && colors.isEmpty()) {
        if (colorMapFile.value().empty()) {
            table->colors = detail::presetColors(preset.value());
        } else {
            colormap::ParaViewColorMap map =
                colormap::readParaViewColorMap(readablePath(colorMapFile.value(), "colour map"));
            table->colors = {std::move(map.positions), std::move(map.colors)};
        }
    } else {
        table->colors = controlPoints<glm::vec3>(context, colorValues, colors, [&](std::size_t i) {
            const glm::vec3& color = colors[i];
            if (!detail::isFiniteColor(color) || glm::any(glm::lessThan(color, glm::vec3(0.0f)))) {
                throw DataError(context + ": " + element(colors, i) +
                                " must be finite and not negative, got " +
                                detail::formatColor(color));
            }
        });
    }
    table->opacities = controlPoints<float>(context, opacityValues, opacities, [&](std::size_t i) {
        const float tau = opacities[i];
        if (!std::isfinite(tau) || tau < 0.0f) {
            throw DataError(context + ": " + element(opacities, i) +
                            " must be finite and not negative (opacity per unit length), got " +
                            sg::formatFloat(tau));
        }
    });

    const float glow = emission.value();
    if (!std::isfinite(glow) || glow < 0.0f) {
        throw DataError(context + ": emission must be finite and not negative, got " +
                        sg::formatFloat(glow));
    }
    table->emission = glow;
    return table;
}

std::shared_ptr<const detail::TransferTable> TransferFunction::table() const {
    const std::lock_guard<std::mutex> lock(mTableMutex);
    if (!mTable) {
        mTable = buildTable();
    }
    return mTable;
}

void TransferFunction::validate() const { table(); }

namespace {

// `value` normalized over `range` and clamped to [0, 1]; NaN stays NaN.
float normalized(const glm::vec2& range, float value) {
    // In double: the difference of two large floats may overflow float.
    const double t = (double(value) - range.x) / (double(range.y) - range.x);
    return std::isnan(t) ? t : static_cast<float>(std::clamp(t, 0.0, 1.0));
}

// The level of normalized position `t` in [0, 1]: the nearest of TransferFunction::kLevels.
int levelOf(float t) {
    return static_cast<int>(t * static_cast<float>(TransferFunction::kLevels - 1) + 0.5f);
}

// The normalized position of level `level`: exact in float (a multiple of 2^-15).
float levelPosition(int level) {
    return static_cast<float>(level) / static_cast<float>(TransferFunction::kLevels - 1);
}

// The classification at normalized position `t` in [0, 1].
Classification classifyAt(const detail::TransferTable& table, float t, const DataScale& scale) {
    const float tau = table.opacities(t) / scale.unitDistance;
    return {table.colors(t) * (tau + table.emission / scale.unitDistance), tau};
}

Classification classifyWith(const detail::TransferTable& table, float value,
                            const DataScale& scale) {
    if (std::isnan(value)) {
        return {};
    }
    return classifyAt(table, normalized(scale.range, value), scale);
}

// The fields as written: `range`, and one world unit for "one voxel" since there is no voxel.
DataScale fixedScale(const detail::TransferTable& table) {
    return {glm::vec2(table.rangeMin, table.rangeMax),
            table.unitDistance > 0.0f ? table.unitDistance : 1.0f};
}

// The scale `checked` gives `grid`'s values: one table throughout, so a change of the node
// between two lookups cannot mix two tables. With `ranges` (the grid's block value ranges), a
// DATA range is their union instead of a scan of the grid: the same finite values.
template <class T>
DataScale scaleOf(const detail::TransferTable& checked, const volume::Grid<T>& grid,
                  const octree::ValueRanges* ranges = nullptr) {
    DataScale scale = fixedScale(checked);
    switch (static_cast<RangeMode>(checked.rangeMode)) {
    case RangeMode::Data:
        // A brick's block ranges are its own: its range is the whole grid's.
        if (!ranges || grid.whole()) {
            scale.range = glm::vec2(detail::valueRange(grid));
        } else if (ranges->blockCount() == 0) {
            scale.range = glm::vec2(0.0f, 1.0f);
        } else {
            const glm::vec2 values = ranges->valueRange();
            scale.range = glm::vec2(detail::widenedRange(values.x, values.y));
        }
        break;
    case RangeMode::Percentile:
        scale.range = glm::vec2(
            detail::percentileRange(grid, checked.percentiles.x, checked.percentiles.y));
        break;
    case RangeMode::Auto:
    case RangeMode::Fixed:
        break;
    }
    if (!(scale.range.x < scale.range.y)) {
        // Values so close together (or so large) that float cannot tell the ends apart.
        scale.range.y = std::nextafter(scale.range.x, std::numeric_limits<float>::infinity());
    }
    if (checked.unitDistance == 0.0f) {
        const glm::dvec3 spacing = grid.geometry().spacing();
        scale.unitDistance = static_cast<float>(std::cbrt(spacing.x * spacing.y * spacing.z));
    }
    return scale;
}

} // namespace

DataScale TransferFunction::dataScale(const volume::ScalarGrid& grid) const {
    return scaleOf(*table(), grid);
}

DataScale TransferFunction::dataScale(const volume::VectorGrid& grid) const {
    return scaleOf(*table(), grid);
}

Classification TransferFunction::classify(float value) const {
    const std::shared_ptr<const detail::TransferTable> checked = table();
    return classifyWith(*checked, value, fixedScale(*checked));
}

Classification TransferFunction::classify(float value, const DataScale& scale) const {
    return classifyWith(*table(), value, scale);
}

Classification TransferFunction::classifyLevel(float value, const DataScale& scale) const {
    if (std::isnan(value)) {
        return {};
    }
    return classifyAt(*table(), levelPosition(levelOf(normalized(scale.range, value))), scale);
}

glm::vec3 TransferFunction::color(float value) const {
    const std::shared_ptr<const detail::TransferTable> checked = table();
    return color(value, fixedScale(*checked));
}

glm::vec3 TransferFunction::color(float value, const DataScale& scale) const {
    if (std::isnan(value)) {
        return glm::vec3(0.0f);
    }
    return table()->colors(normalized(scale.range, value));
}

glm::vec3 TransferFunction::colorAt(float t) const {
    return table()->colors(std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 1.0f));
}

namespace {

// Whether `map` is zero all over [t0, t1]: at both ends and at every control point between (the
// map is linear between control points, so that is all of it; y >= 0 is not assumed).
template <class Y> bool isZeroBetween(const detail::PiecewiseLinear<Y>& map, float t0, float t1) {
    if (map(t0) != Y(0.0f) || map(t1) != Y(0.0f)) {
        return false;
    }
    for (std::size_t i = 0; i < map.x.size(); ++i) {
        if (map.x[i] >= t0 && map.x[i] <= t1 && map.y[i] != Y(0.0f)) {
            return false;
        }
    }
    return true;
}

// TransferFunction::isTransparentBetween() with the table `checked`.
bool isTransparentWith(const detail::TransferTable& checked, float minimum, float maximum,
                       const DataScale& scale) {
    // normalized() and the levels do not decrease with the value, so the range's ends bound
    // every t in it and every level of them.
    const float low = normalized(scale.range, minimum);
    const float high = normalized(scale.range, maximum);
    if (!(low <= high)) {
        return false;
    }
    const float t0 = std::min(low, levelPosition(levelOf(low)));
    const float t1 = std::max(high, levelPosition(levelOf(high)));
    if (!isZeroBetween(checked.opacities, t0, t1)) {
        return false;
    }
    // With no extinction, classifyWith() gives colour * emission per unit length.
    return checked.emission / scale.unitDistance == 0.0f || isZeroBetween(checked.colors, t0, t1);
}

} // namespace

bool TransferFunction::isTransparentBetween(float minimum, float maximum,
                                            const DataScale& scale) const {
    return isTransparentWith(*table(), minimum, maximum, scale);
}

namespace {

constexpr const char* kClassifyStep = "classifying";

// The palette of a scalar classification (octree::ClassifiedGrid::Storage::Palette): index 0
// the empty voxel, index k >= 1 the function at level k − 1; made in parallel.
std::vector<glm::vec4> paletteOf(const detail::TransferTable& checked, const DataScale& scale) {
    std::vector<glm::vec4> palette(TransferFunction::kLevels + 1, glm::vec4(0.0f));
    tbb::parallel_for(0, TransferFunction::kLevels, [&](int level) {
        const Classification medium = classifyAt(checked, levelPosition(level), scale);
        palette[static_cast<std::size_t>(level + 1)] = glm::vec4(medium.color, medium.extinction);
    });
    return palette;
}

// The palette index of `value` (not empty, not NaN): its level's, or 0 where that level's
// medium is empty.
std::uint16_t paletteIndex(const std::vector<glm::vec4>& palette, const glm::vec2& range,
                           float value) {
    const float t = normalized(range, value);
    if (std::isnan(t)) {
        return 0;
    }
    const auto index = static_cast<std::uint16_t>(1 + levelOf(t));
    return palette[index] != glm::vec4(0.0f) ? index : std::uint16_t{0};
}

// Classifies the non-empty voxels of `grid`'s blocks for which `isWanted(block)` holds (block
// coordinates), telling `progress` the fraction of the blocks done; with `recording`, adds the
// value range of every block that holds a non-empty voxel to it. A block whose value range the
// function shows nothing of is not classified voxel by voxel: it would allocate nothing (the
// test is exact that way round), and most blocks of a thresholded dense volume are such. The
// blocks are read and classified in parallel (oneTBB), a batch at a time, and put into the grid
// in order: the same grid for any number of threads. Each voxel holds the index of its value's
// level in the grid's palette (paletteOf()): 2 bytes a voxel, classifyLevel().
template <class IsWanted>
std::shared_ptr<octree::ClassifiedGrid>
classifyBlocks(const detail::TransferTable& checked, const DataScale& scale,
               const volume::ScalarGrid& grid, const sg::WorkProgress& progress,
               octree::ValueRanges* recording, IsWanted&& isWanted) {
    using ClassifiedBlock = octree::ClassifiedGrid::PaletteBlock;
    const volume::GridGeometry& geometry = grid.geometry();
    auto classified =
        std::make_shared<octree::ClassifiedGrid>(glm::u64vec3(geometry.dims()), geometry.spacing(),
                                                 geometry.origin(), paletteOf(checked, scale));
    const std::vector<glm::vec4>& palette = classified->palette();
    const std::vector<glm::i64vec3> blocks = grid.occupiedBlocks();
    std::vector<ClassifiedBlock> batch(std::min(blocks.size(), volume::kBlocksPerBatch));
    std::vector<std::uint32_t> nonEmpty(batch.size());
    std::vector<glm::vec2> ranges(batch.size());
    const auto classifyBlock = [&](std::size_t i, const glm::i64vec3& block) {
        nonEmpty[i] = 0;
        const bool wanted = isWanted(glm::u64vec3(block));
        if (!wanted && recording == nullptr) {
            return;
        }
        volume::ScalarGrid::VoxelBlock voxels;
        grid.readBlock(block, voxels);
        const glm::vec2 range = volume::valueRangeOf(voxels);
        ranges[i] = range;
        if (!wanted || !(range.x <= range.y) ||
            isTransparentWith(checked, range.x, range.y, scale)) {
            return;
        }
        ClassifiedBlock& out = batch[i];
        for (std::size_t v = 0; v < voxels.values.size(); ++v) {
            const std::uint16_t index =
                voxels.nonEmpty[v] ? paletteIndex(palette, scale.range, voxels.values[v]) : 0;
            out[v] = index;
            nonEmpty[i] += index != 0 ? 1 : 0;
        }
    };
    const auto takeBlock = [&](std::size_t i, const glm::i64vec3& block) {
        if (recording != nullptr && ranges[i].x <= ranges[i].y) {
            recording->addBlock(glm::u64vec3(block), ranges[i]);
        }
        if (nonEmpty[i] > 0) {
            classified->setBlock(glm::u64vec3(block), batch[i]);
        }
    };
    volume::inBlockBatches(blocks, progress, kClassifyStep, classifyBlock, takeBlock);
    return classified;
}

} // namespace

std::shared_ptr<octree::ClassifiedGrid>
TransferFunction::classify(const volume::ScalarGrid& grid, const octree::ValueRanges& ranges,
                           const sg::WorkProgress& progress) const {
    const std::shared_ptr<const detail::TransferTable> checked = table();
    const DataScale scale = scaleOf(*checked, grid, &ranges);
    const std::vector<bool> visible = ranges.visibleBlocks([&](float minimum, float maximum) {
        return !isTransparentBetween(minimum, maximum, scale);
    });
    return classifyBlocks(*checked, scale, grid, progress, nullptr, [&](glm::u64vec3 block) {
        return ranges.isVisibleBlock(visible, block * octree::ClassifiedGrid::kBlockSize);
    });
}

std::shared_ptr<octree::ClassifiedGrid>
TransferFunction::classifyRecording(const volume::ScalarGrid& grid, octree::ValueRanges& ranges,
                                    const sg::WorkProgress& progress) const {
    const std::shared_ptr<const detail::TransferTable> checked = table();
    return classifyBlocks(*checked, scaleOf(*checked, grid), grid, progress, &ranges,
                          [](glm::u64vec3) { return true; });
}

std::shared_ptr<octree::ClassifiedGrid>
TransferFunction::classifyBlockMeans(const volume::ScalarGrid& grid,
                                     const octree::ValueRanges& ranges,
                                     const octree::ValueHistograms& histograms) const {
    constexpr double kBlockSize = octree::ClassifiedGrid::kBlockSize;
    const std::shared_ptr<const detail::TransferTable> checked = table();
    const DataScale scale = scaleOf(*checked, grid, &ranges);
    const volume::GridGeometry& geometry = grid.geometry();
    const glm::dvec3 spacing = geometry.spacing();
    auto means = std::make_shared<octree::ClassifiedGrid>(
        octree::ClassifiedGrid::boxBlockDims(glm::u64vec3(geometry.dims())), spacing * kBlockSize,
        geometry.origin() + spacing * ((kBlockSize - 1.0) / 2.0));
    const std::vector<octree::ValueHistograms::Block>& blocks = histograms.blocks();
    std::vector<glm::vec4> blockMeans(blocks.size());
    tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t b) {
        const octree::ValueHistograms::Block& block = blocks[b];
        glm::vec4 sum(0.0f);
        if (!isTransparentWith(*checked, block.range.x, block.range.y, scale)) {
            for (std::size_t bin = 0; bin < block.counts.size(); ++bin) {
                if (block.counts[bin] > 0) {
                    const Classification result = classifyWith(*checked, block.means[bin], scale);
                    sum += static_cast<float>(block.counts[bin]) *
                           glm::vec4(result.color, result.extinction);
                }
            }
        }
        blockMeans[b] = sum / static_cast<float>(octree::ClassifiedGrid::kBlockVoxels);
    });
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        means->setVoxel(blocks[b].coordinates, glm::vec3(blockMeans[b]), blockMeans[b].w);
    }
    return means;
}

std::shared_ptr<octree::ClassifiedGrid>
TransferFunction::classify(const volume::ScalarGrid& grid) const {
    const std::shared_ptr<const detail::TransferTable> checked = table();
    return classifyBlocks(*checked, scaleOf(*checked, grid), grid, {}, nullptr,
                          [](glm::u64vec3) { return true; });
}

void TransferFunction::doAction(sg::Action& action) {
    action.state().modify<TransferFunctionElement>().transferFunction = this;
}

void TransferFunction::notify(const sg::Field* source) {
    if (isLabelField(source) || isShadingField(source)) {
        sg::Node::notify(source); // the checked tables stay as they are
        return;
    }
    {
        const std::lock_guard<std::mutex> lock(mTableMutex);
        mTable.reset();
    }
    sg::Node::notify(source);
}

} // namespace texsplat::nodes
