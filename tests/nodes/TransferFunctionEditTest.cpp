// Transfer-function edits without a new data hierarchy (issue 13): a scalar grid's block value
// ranges and histograms are made once and serve every transfer function; classification with
// them skips the blocks a function hides and gives the same classified grid, an edit after the
// first frame draws what a fresh scene with the new function draws, and an interactive frame
// previews an edit from the blocks' histograms without classifying.
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
#include "nodes/volume/ValueHistogram.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Octree.h"
#include "octree/ValueHistograms.h"
#include "octree/ValueRanges.h"
#include "scenegraph/Separator.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
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
    EXPECT_EQ(volume::blockValueHistograms(*grid).blocks().size(), ranges.blockCount());
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
// non-finite voxels, classifies voxel for voxel as each value alone does (at its level,
// TransferFunction::classifyLevel()).
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
            const Classification alone = transfer->classifyLevel(value, scale);
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

// Every block's mean classification, as the octree's block nodes hold it: from the classified
// grid, and from the histograms without classifying. Where each bin of a block holds one distinct
// value (the data in steps of 1/8, bins at most 1/16 wide) the two agree for any function,
// steps included; for other data, where the function is linear over a block's values (the
// extinction of an opacity ramp; the colour map bends, so colours only come close).
TEST_F(TransferFunctionEdit, theBlockMeansFromTheHistogramsAreTheClassifiedBlocksMeans) {
    const auto balls = twoBalls();
    auto stepped = std::make_shared<volume::SparseScalarGrid>(balls->geometry());
    balls->forEachActive([&](const glm::i64vec3& index, float value) {
        stepped->setValue(index, std::round(value * 8.0f) / 8.0f);
    });
    struct Case {
        std::shared_ptr<volume::SparseScalarGrid> grid;
        TransferFunction::Ptr transfer;
        float colorTolerance; // of 1 + the expected value
    };
    const std::vector<Case> cases{
        {stepped, ramp({0.0f, 0.3f, 0.3f, 0.6f, 1.0f}, {0.0f, 0.0f, 2.0f, 0.5f, 3.0f}), 1e-5f},
        {stepped, ramp({0.0f, 0.1f, 0.7f}, {0.0f, 4.0f, 0.0f}), 1e-5f},
        {balls, ramp({0.0f, 1.0f}, {0.0f, 2.0f}), 1e-3f}};
    for (std::size_t c = 0; c < cases.size(); ++c) {
        SCOPED_TRACE(c);
        const volume::ScalarGrid& grid = *cases[c].grid;
        const TransferFunction& transfer = *cases[c].transfer;
        octree::ValueRanges ranges(glm::u64vec3(64));
        const auto classified = transfer.classifyRecording(grid, ranges);
        const octree::ValueHistograms histograms = volume::blockValueHistograms(grid);
        const auto means = transfer.classifyBlockMeans(grid, ranges, histograms);
        EXPECT_EQ(means->dims(), glm::u64vec3(8));
        EXPECT_EQ(means->spacing(), glm::dvec3(8.0));
        EXPECT_EQ(means->origin(), glm::dvec3(3.5));
        std::size_t compared = 0;
        for (std::uint64_t z = 0; z < 8; ++z)
            for (std::uint64_t y = 0; y < 8; ++y)
                for (std::uint64_t x = 0; x < 8; ++x) {
                    glm::vec4 sum(0.0f);
                    for (std::uint64_t v = 0; v < 512; ++v) {
                        sum += classified->voxel(glm::u64vec3(x, y, z) * std::uint64_t{8} +
                                                 glm::u64vec3(v % 8, v / 8 % 8, v / 64));
                    }
                    const glm::vec4 expected = sum / 512.0f;
                    const glm::vec4 got = means->voxel({x, y, z});
                    for (int channel = 0; channel < 4; ++channel) {
                        const float tolerance = channel < 3 ? cases[c].colorTolerance : 1e-5f;
                        EXPECT_NEAR(got[channel], expected[channel],
                                    tolerance * (1.0f + expected[channel]))
                            << "block " << x << ' ' << y << ' ' << z << " channel " << channel;
                    }
                    compared += expected != glm::vec4(0.0f) ? 1 : 0;
                }
        EXPECT_GE(compared, 16u);
        EXPECT_EQ(means->blockCount(), 1u) << "an 8³ grid of means is one block";
    }
}

// The same against the octree's block nodes, in a grid whose box is no multiple of 8 blocks,
// with anisotropic spacing and an origin: a whole block's cell holds its node's mean where its
// node's splat goes; a block clipped by the grid's upper faces holds its voxels' sum over 512
// (the same extinction in all) at the whole block's centre.
TEST_F(TransferFunctionEdit, theBlockMeansAreTheOctreesBlockNodes) {
    const volume::GridGeometry geometry(glm::i64vec3(70, 64, 67), glm::dvec3(1.0, -2.0, 3.0),
                                        glm::dvec3(2.0, 1.0, 0.5));
    volume::SparseScalarGrid grid(geometry);
    for (std::int64_t z = 0; z < 67; ++z)
        for (std::int64_t y = 0; y < 64; ++y)
            for (std::int64_t x = 0; x < 70; ++x) {
                const double r =
                    glm::length(glm::dvec3(x, y, z) - glm::dvec3(40.0, 30.0, 45.0)) / 36.0;
                if (r < 1.0) {
                    grid.setValue({x, y, z}, std::round(static_cast<float>(1.0 - r) * 8.0f) / 8.0f);
                }
            }
    const auto transfer = ramp({0.0f, 0.3f, 0.3f, 1.0f}, {0.0f, 0.0f, 1.0f, 2.0f});
    octree::ValueRanges ranges(glm::u64vec3(geometry.dims()));
    const std::shared_ptr<const octree::ClassifiedGrid> classified =
        transfer->classifyRecording(grid, ranges);
    const auto means =
        transfer->classifyBlockMeans(grid, ranges, volume::blockValueHistograms(grid));
    EXPECT_EQ(means->dims(), glm::u64vec3(9, 8, 9));
    const octree::Octree octree(classified);
    std::size_t whole = 0;
    std::size_t clipped = 0;
    const auto compare = [&](const octree::NodeRef& node) {
        const glm::vec4 cell = means->voxel(node.coord);
        const octree::OctreeNode summary = octree.node(node);
        const glm::vec4 mean(summary.meanColor, summary.meanExtinction);
        const auto voxels = static_cast<float>(octree.voxelCount(node));
        for (int channel = 0; channel < 4; ++channel) {
            EXPECT_NEAR(cell[channel] * 512.0f, mean[channel] * voxels,
                        1e-4f * (1.0f + mean[channel] * voxels));
        }
        const glm::dvec3 blockCentre = geometry.origin() + geometry.spacing() *
                                                               (glm::dvec3(node.coord) * 8.0 + 3.5);
        EXPECT_EQ(means->toWorld(glm::dvec3(node.coord)), blockCentre);
        if (octree.voxelCount(node) == 512) {
            EXPECT_EQ(octree.center(node), blockCentre);
            ++whole;
        } else {
            ++clipped;
        }
    };
    const std::function<void(const octree::NodeRef&)> walk = [&](const octree::NodeRef& node) {
        if (node.level == octree::ClassifiedGrid::kBlockLevel) {
            compare(node);
            return;
        }
        std::array<octree::NodeRef, 8> children;
        const int count = octree.children(node, children);
        for (int c = 0; c < count; ++c) {
            walk(children[static_cast<std::size_t>(c)]);
        }
    };
    ASSERT_FALSE(octree.isEmpty());
    walk(octree.root());
    EXPECT_GT(whole, 50u);
    EXPECT_GT(clipped, 10u);
    EXPECT_EQ(whole + clipped, means->nonEmptyVoxelCount());
}

struct Rendered {
    image::Image image;
    sg::FrameBuilds builds;
};

// A frame of `root`; an interactive one previews edits of grids storing `previewVoxels` voxels
// or more (by default every grid: the two balls are a small one).
Rendered renderFrame(sg::Node& root, bool interactive = false, std::uint64_t previewVoxels = 0) {
    render::FrameAction action(72, 64);
    action.setInteractive(interactive);
    action.setPreviewMinimumVoxels(previewVoxels);
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

TEST_F(TransferFunctionEdit, aNewTitleOrUnitClassifiesNothingAgain) {
    const auto transfer = ramp({0.0f, 1.0f}, {0.0f, 2.0f});
    const sg::Node::Ptr labelled = scene(transfer, 0);
    const Rendered first = renderFrame(*labelled);
    transfer->title.setValue("Density");
    transfer->units.setValue("g/cm³");
    const Rendered retitled = renderFrame(*labelled);
    EXPECT_EQ(retitled.builds.classifications, 0u);
    EXPECT_EQ(differingPixels(retitled.image, first.image), 0);
    transfer->emission.setValue(0.5f);
    EXPECT_EQ(renderFrame(*labelled).builds.classifications, 1u) << "other fields still do";
}

// The sum of `image`'s opacities: how much of the background it covers.
double coverage(const image::Image& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            sum += static_cast<double>(image.pixel(x, y).a);
        }
    return sum;
}

TEST_F(TransferFunctionEdit, anInteractiveFrameAfterAnEditPreviewsItWithoutClassifying) {
    for (const int maxSplats : {0, 20}) { // every block mean, and a cut of them
        SCOPED_TRACE(maxSplats);
        const auto transfer = ramp({0.0f, 1.0f}, {0.0f, 2.0f});
        const sg::Node::Ptr edited = scene(transfer, maxSplats);
        const Rendered unedited = renderFrame(*edited, true);
        EXPECT_EQ(unedited.builds.classifications, 1u) << "nothing to preview before a first frame";
        EXPECT_EQ(unedited.builds.previews, 0u);
        EXPECT_EQ(differingPixels(renderFrame(*edited, true).image, unedited.image), 0)
            << "no edit, no preview: the exact frame";
        transfer->opacityValues.setValue({0.0f, 0.3f, 1.0f});
        transfer->opacities.setValue({0.0f, 0.0f, 3.0f});
        const Rendered preview = renderFrame(*edited, true);
        EXPECT_EQ(preview.builds.classifications, 0u);
        EXPECT_EQ(preview.builds.octrees, 0u);
        EXPECT_EQ(preview.builds.valueHistograms, 1u) << "for the grid's first preview";
        EXPECT_EQ(preview.builds.previews, 1u);
        const Rendered previewAgain = renderFrame(*edited, true);
        EXPECT_EQ(previewAgain.builds.previews, 0u) << "kept until the function changes";
        EXPECT_EQ(differingPixels(previewAgain.image, preview.image), 0);
        // The same preview from a scene that started with another function.
        const auto other = ramp({0.0f, 0.5f, 1.0f}, {1.0f, 0.0f, 1.0f});
        const sg::Node::Ptr otherScene = scene(other, maxSplats);
        renderFrame(*otherScene);
        other->opacityValues.setValue({0.0f, 0.3f, 1.0f});
        other->opacities.setValue({0.0f, 0.0f, 3.0f});
        EXPECT_EQ(differingPixels(renderFrame(*otherScene, true).image, preview.image), 0);
        // The next frame that is not interactive is exact: a fresh scene's.
        const Rendered exact = renderFrame(*edited);
        EXPECT_EQ(exact.builds.classifications, 1u);
        EXPECT_EQ(exact.builds.valueRanges, 0u);
        EXPECT_EQ(differingPixels(
                      exact.image,
                      renderFrame(*scene(ramp({0.0f, 0.3f, 1.0f}, {0.0f, 0.0f, 3.0f}), maxSplats))
                          .image),
                  0);
        // The preview shows the edit: a cut of the preview covers about what the exact cut after
        // the edit covers, and the edit changed that a lot. (Every block mean covers more than
        // the full-resolution image: a block's splat spreads its mean extinction over 8³ voxels
        // and 1 - e^-τ is concave; the octree's block nodes do the same.)
        if (maxSplats > 0) {
            EXPECT_LT(std::abs(coverage(preview.image) - coverage(exact.image)),
                      0.2 * std::abs(coverage(unedited.image) - coverage(exact.image)));
        }
        // The next edit makes a new preview.
        transfer->opacities.setValue({0.0f, 0.0f, 1.0f});
        const Rendered nextPreview = renderFrame(*edited, true);
        EXPECT_EQ(nextPreview.builds.previews, 1u);
        EXPECT_EQ(nextPreview.builds.valueHistograms, 0u) << "made once per grid";
        EXPECT_GT(differingPixels(nextPreview.image, preview.image), 100);
    }
}

// A preview follows the function the frame has, whichever node that is, and keeps no grid alive
// once the volume has another.
TEST_F(TransferFunctionEdit, aPreviewFollowsTheCurrentFunctionAndGrid) {
    auto data = VolumeData::create();
    std::shared_ptr<volume::SparseScalarGrid> first = twoBalls();
    data->setGrid(volume::ScalarGridPtr(first));
    const auto transfer = ramp({0.0f, 1.0f}, {0.0f, 2.0f});
    auto group = sg::Separator::create();
    group->addChild(data);
    group->addChild(transfer);
    group->addChild(TextureSplat::create());
    const sg::Node::Ptr root = render::framedScene(group, 72.0f / 64.0f);
    renderFrame(*root);
    // Another TransferFunction node in the same place: previewed, and its edits are heard.
    const auto other = ramp({0.0f, 0.5f, 1.0f}, {0.0f, 0.0f, 3.0f});
    group->replaceChild(1, other);
    const Rendered switched = renderFrame(*root, true);
    EXPECT_EQ(switched.builds.previews, 1u);
    other->opacities.setValue({0.0f, 0.0f, 1.0f});
    const Rendered edited = renderFrame(*root, true);
    EXPECT_EQ(edited.builds.previews, 1u) << "an edit of the new node makes a new preview";
    EXPECT_GT(differingPixels(edited.image, switched.image), 100);
    // A new grid: classified exactly (nothing to preview it from yet); the old one is let go.
    const std::weak_ptr<volume::SparseScalarGrid> firstGrid = first;
    data->setGrid(volume::ScalarGridPtr(twoBalls()));
    first.reset();
    const Rendered reloaded = renderFrame(*root, true);
    EXPECT_EQ(reloaded.builds.previews, 0u);
    EXPECT_EQ(reloaded.builds.valueRanges, 1u);
    EXPECT_TRUE(firstGrid.expired()) << "no preview or cache holds the old grid";
}

// A grid that classifies in milliseconds is not previewed: the viewer's default threshold.
TEST_F(TransferFunctionEdit, anInteractiveFrameClassifiesAnEditOfASmallGridExactly) {
    const auto transfer = ramp({0.0f, 1.0f}, {0.0f, 2.0f});
    const sg::Node::Ptr edited = scene(transfer, 400);
    renderFrame(*edited);
    transfer->opacities.setValue({0.0f, 1.0f});
    const std::uint64_t stored = twoBalls()->storedVoxelCount();
    const Rendered exact = renderFrame(*edited, true, stored + 1);
    EXPECT_EQ(exact.builds.previews, 0u);
    EXPECT_EQ(exact.builds.classifications, 1u);
    transfer->opacities.setValue({0.0f, 3.0f});
    const Rendered preview = renderFrame(*edited, true, stored);
    EXPECT_EQ(preview.builds.previews, 1u) << "from that many stored voxels on";
    EXPECT_EQ(preview.builds.classifications, 0u);
    EXPECT_GT(render::FrameAction(1, 1).previewMinimumVoxels(), stored);
}

} // namespace
} // namespace texsplat::nodes
