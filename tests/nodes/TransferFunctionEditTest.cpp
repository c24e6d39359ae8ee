// Transfer-function edits without a new data hierarchy (issue 13): a scalar grid's block value
// ranges are made once and serve every transfer function; classification with them skips the
// blocks a function hides and gives the same classified grid, and an edit after the first frame
// draws what a fresh scene with the new function draws.
#include "nodes/volume/SparseGrid.h"

#include "nodes/NodeTypes.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/Frame.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/volume/DenseGrid.h"
#include "octree/ClassifiedGrid.h"
#include "octree/ValueRanges.h"
#include "scenegraph/Separator.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace texsplat::nodes {
namespace {

// Two balls in a 64³ box: a dense one with values from 0 to 1 around voxel (20, 22, 24), and a
// faint one (values up to 0.2) around (46, 44, 40), so that a function hiding low values hides
// whole blocks.
std::shared_ptr<volume::SparseScalarGrid> twoBalls() {
    auto grid = std::make_shared<volume::SparseScalarGrid>(volume::GridGeometry(glm::i64vec3(64)));
    const auto addBall = [&](glm::dvec3 centre, double radius, double peak) {
        for (std::int64_t z = 0; z < 64; ++z)
            for (std::int64_t y = 0; y < 64; ++y)
                for (std::int64_t x = 0; x < 64; ++x) {
                    const double r = glm::length(glm::dvec3(x, y, z) - centre) / radius;
                    if (r < 1.0) {
                        grid->setValue(glm::i64vec3(x, y, z), static_cast<float>(peak * (1.0 - r)));
                    }
                }
    };
    addBall({20.0, 22.0, 24.0}, 13.0, 1.0);
    addBall({46.0, 44.0, 40.0}, 9.0, 0.2);
    return grid;
}

TransferFunction::Ptr ramp(std::vector<float> values, std::vector<float> opacities) {
    auto transfer = TransferFunction::create();
    transfer->rangeMode.setValue(RangeMode::Fixed);
    transfer->range.setValue(glm::vec2(0.0f, 1.0f));
    transfer->preset.setValue(ColorPreset::Viridis);
    transfer->opacityValues.setValue(std::move(values));
    transfer->opacities.setValue(std::move(opacities));
    return transfer;
}

class TransferFunctionEdit : public ::testing::Test {
protected:
    void SetUp() override { registerNodeTypes(); }
};

TEST_F(TransferFunctionEdit, aRangeIsTransparentOnlyWhereEveryValueInItIs) {
    // Zero up to t = 0.3, rising to 1 at t = 0.6; a step at 0.8 back to zero.
    const auto transfer = ramp({0.0f, 0.3f, 0.6f, 0.8f, 0.8f, 1.0f},
                               {0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 0.0f});
    const DataScale scale{glm::vec2(0.0f, 1.0f), 1.0f};
    EXPECT_TRUE(transfer->isTransparentBetween(-5.0f, 0.3f, scale)); // below the range too
    EXPECT_FALSE(transfer->isTransparentBetween(0.1f, 0.31f, scale));
    EXPECT_FALSE(transfer->isTransparentBetween(0.5f, 0.5f, scale));
    EXPECT_FALSE(transfer->isTransparentBetween(0.0f, 1.0f, scale)); // spans the bump
    EXPECT_TRUE(transfer->isTransparentBetween(0.81f, 7.0f, scale));
    // Glow without absorption: transparent only where the colour is black too.
    transfer->emission.setValue(0.5f);
    transfer->preset.setValue(ColorPreset::Hot); // black at t = 0 only
    EXPECT_FALSE(transfer->isTransparentBetween(0.0f, 0.3f, scale));
    EXPECT_TRUE(transfer->isTransparentBetween(-1.0f, 0.0f, scale));
}

// The classified grid with and without the value ranges, for functions that hide whole blocks,
// steps, glow, and a DATA range (read from the ranges instead of a scan): equal voxel for voxel.
TEST_F(TransferFunctionEdit, classifyingWithTheValueRangesGivesTheSameGrid) {
    const auto grid = twoBalls();
    octree::ValueRanges added(glm::u64vec3(64));
    grid->forEachActive([&](const glm::i64vec3& index, float value) {
        added.add(glm::u64vec3(index), value);
    });
    // A grid's first classification records the ranges on the way.
    octree::ValueRanges ranges(glm::u64vec3(64));
    const auto first = ramp({0.0f, 1.0f}, {0.0f, 2.0f})->classifyRecording(*grid, ranges);
    EXPECT_EQ(ranges.blockCount(), added.blockCount());
    EXPECT_EQ(ranges.valueRange(), added.valueRange());
    const auto straddles = [](float low, float high) { return low < 0.05f && high > 0.1f; };
    // The same blocks visible (the slots may be in another order: blocks are recorded in
    // parallel batches, voxels one by one).
    const std::vector<bool> recordedVisible = ranges.visibleBlocks(straddles);
    const std::vector<bool> addedVisible = added.visibleBlocks(straddles);
    std::size_t visibleVoxels = 0;
    std::size_t disagreeing = 0;
    grid->forEachActive([&](const glm::i64vec3& index, float) {
        const bool visible = ranges.isVisibleBlock(recordedVisible, glm::u64vec3(index));
        visibleVoxels += visible ? 1 : 0;
        disagreeing += visible != added.isVisibleBlock(addedVisible, glm::u64vec3(index)) ? 1 : 0;
    });
    EXPECT_GT(visibleVoxels, 0u);
    EXPECT_EQ(disagreeing, 0u);
    EXPECT_EQ(first->nonEmptyVoxelCount(),
              ramp({0.0f, 1.0f}, {0.0f, 2.0f})->classify(*grid)->nonEmptyVoxelCount());
    std::vector<TransferFunction::Ptr> transfers{
        ramp({0.0f, 1.0f}, {0.0f, 2.0f}),
        ramp({0.0f, 0.25f, 1.0f}, {0.0f, 0.0f, 3.0f}),
        ramp({0.0f, 0.5f, 0.5f, 1.0f}, {0.0f, 0.0f, 1.0f, 1.0f}),
        ramp({0.0f, 0.1f, 0.15f, 0.3f}, {0.0f, 4.0f, 0.0f, 0.0f})};
    auto glowing = ramp({0.0f, 0.4f, 1.0f}, {0.0f, 0.0f, 1.0f});
    glowing->emission.setValue(2.0f);
    glowing->preset.setValue(ColorPreset::Hot);
    transfers.push_back(glowing);
    auto data = ramp({0.0f, 0.5f, 1.0f}, {0.0f, 0.0f, 2.0f});
    data->rangeMode.setValue(RangeMode::Data);
    transfers.push_back(data);
    std::size_t hiddenBlocks = 0;
    for (std::size_t i = 0; i < transfers.size(); ++i) {
        SCOPED_TRACE(i);
        const TransferFunction& transfer = *transfers[i];
        const auto plain = transfer.classify(*grid);
        const auto fast = transfer.classify(*grid, ranges);
        EXPECT_EQ(fast->blockCount(), plain->blockCount());
        EXPECT_EQ(fast->nonEmptyVoxelCount(), plain->nonEmptyVoxelCount());
        std::size_t differing = 0;
        grid->forEachActive([&](const glm::i64vec3& index, float) {
            differing += fast->voxel(glm::u64vec3(index)) != plain->voxel(glm::u64vec3(index));
        });
        EXPECT_EQ(differing, 0u);
        const DataScale scale = transfer.dataScale(*grid);
        for (const bool visible : ranges.visibleBlocks([&](float low, float high) {
                 return !transfer.isTransparentBetween(low, high, scale);
             })) {
            hiddenBlocks += visible ? 0 : 1;
        }
    }
    EXPECT_GT(hiddenBlocks, 50u) << "the functions hide whole blocks, which are skipped";
}

// A grid's first classification (no value ranges yet) skips the blocks whose own values the
// function hides too: a thresholded dense field, with clipped blocks at the box's far sides and
// non-finite voxels, classifies voxel for voxel as each value alone does.
TEST_F(TransferFunctionEdit, aFirstClassificationGivesEveryVoxelWhatItsValueClassifiesTo) {
    volume::DenseScalarGrid grid(volume::GridGeometry(glm::i64vec3(45, 38, 41)));
    for (std::int64_t z = 0; z < 41; ++z)
        for (std::int64_t y = 0; y < 38; ++y)
            for (std::int64_t x = 0; x < 45; ++x) {
                const glm::i64vec3 index(x, y, z);
                const double r = glm::length(glm::dvec3(index) - glm::dvec3(14, 20, 25)) / 30.0;
                const bool hole = (x * 7 + y * 13 + z * 29) % 101 == 0;
                grid.setValue(index, hole ? std::numeric_limits<float>::quiet_NaN()
                                          : static_cast<float>(1.0 - r));
            }
    for (const auto& transfer : {ramp({0.0f, 0.7f, 0.7f, 1.0f}, {0.0f, 0.0f, 1.0f, 2.0f}),
                                 ramp({0.0f, 0.5f, 0.9f}, {0.0f, 1.0f, 0.0f})}) {
        octree::ValueRanges ranges(glm::u64vec3(45, 38, 41));
        const auto classified = transfer->classifyRecording(grid, ranges);
        const DataScale scale = transfer->dataScale(grid);
        std::size_t visible = 0;
        std::size_t differing = 0;
        grid.forEachActive([&](const glm::i64vec3& index, float value) {
            const Classification alone = transfer->classify(value, scale);
            const glm::vec4 expected(alone.color, alone.extinction);
            visible += expected != glm::vec4(0.0f) ? 1 : 0;
            differing += classified->voxel(glm::u64vec3(index)) != expected ? 1 : 0;
        });
        EXPECT_GT(visible, 1000u);
        EXPECT_EQ(differing, 0u);
        EXPECT_EQ(classified->nonEmptyVoxelCount(), visible);
        std::size_t hiddenBlocks = 0;
        for (const bool shown : ranges.visibleBlocks([&](float low, float high) {
                 return !transfer->isTransparentBetween(low, high, scale);
             })) {
            hiddenBlocks += shown ? 0 : 1;
        }
        EXPECT_GT(hiddenBlocks, 10u) << "whole blocks hidden, which classification skips";
    }
}

struct Rendered {
    image::Image image;
    sg::FrameBuilds builds;
};

Rendered renderFrame(sg::Node& root) {
    render::FrameAction action(72, 64);
    const render::cpu::CpuRenderer renderer(2);
    image::Image image = renderer.draw(action.collect(root), action.statistics(), false);
    return {std::move(image), action.statistics().builds};
}

sg::Node::Ptr scene(const TransferFunction::Ptr& transfer, int maxSplats) {
    auto data = VolumeData::create();
    data->setGrid(volume::ScalarGridPtr(twoBalls()));
    auto splat = TextureSplat::create();
    splat->maxSplats.setValue(maxSplats);
    auto root = sg::Separator::create();
    root->addChild(data);
    root->addChild(transfer);
    root->addChild(splat);
    return render::framedScene(root, 72.0f / 64.0f);
}

// Pixels that differ between `a` and `b`, images of one size.
int differingPixels(const image::Image& a, const image::Image& b) {
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    int differing = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            differing += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    return differing;
}

TEST_F(TransferFunctionEdit, anEditKeepsTheValueRangesAndDrawsWhatAFreshSceneDraws) {
    for (const int maxSplats : {0, 400}) { // full resolution, and a budgeted cut
        SCOPED_TRACE(maxSplats);
        const auto transfer = ramp({0.0f, 1.0f}, {0.0f, 2.0f});
        const sg::Node::Ptr edited = scene(transfer, maxSplats);
        const Rendered first = renderFrame(*edited);
        EXPECT_EQ(first.builds.valueRanges, 1u);
        EXPECT_EQ(first.builds.classifications, 1u);
        EXPECT_EQ(first.builds.octrees, maxSplats > 0 ? 1u : 0u);
        const Rendered again = renderFrame(*edited);
        EXPECT_EQ(again.builds.classifications, 0u) << "nothing changed, nothing is made";
        // Hide the faint ball and the dense one's rim.
        transfer->opacityValues.setValue({0.0f, 0.3f, 1.0f});
        transfer->opacities.setValue({0.0f, 0.0f, 3.0f});
        const Rendered afterEdit = renderFrame(*edited);
        EXPECT_EQ(afterEdit.builds.valueRanges, 0u) << "the data hierarchy is not rebuilt";
        EXPECT_EQ(afterEdit.builds.classifications, 1u);
        const Rendered fresh =
            renderFrame(*scene(ramp({0.0f, 0.3f, 1.0f}, {0.0f, 0.0f, 3.0f}), maxSplats));
        EXPECT_EQ(fresh.builds.valueRanges, 1u);
        EXPECT_EQ(differingPixels(afterEdit.image, fresh.image), 0);
        EXPECT_GT(differingPixels(afterEdit.image, first.image), 100) << "the edit shows";
    }
}

} // namespace
} // namespace texsplat::nodes
