// Octree cuts drawn by a splat node (maxSplats, errorThreshold) on the tornado example, by the CPU
// backend: no seam down the split plane the eye lies on, and an error threshold that means the
// same whatever the transfer function's opacity scale.

#include "nodes/NodeTypes.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/ScalarSplat.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/image/Image.h"
#include "nodes/volume/ExternalGrid.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "octree/SplatEmission.h"
#include "scenegraph/Separator.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

constexpr int kSize = 512;

struct Rendered {
    image::Image image;
    std::size_t splats = 0;
};

// examples/tornado.iv: a 64³ grid seen by a perspective camera whose eye lies on the octree's
// central x plane (x = 0.5 of the unit cube), which the image shows as its middle column.
std::shared_ptr<sg::Separator> tornado() {
    registerNodeTypes();
    return std::dynamic_pointer_cast<sg::Separator>(
        sg::SceneReader::readFile(std::string(TEXSPLAT_SOURCE_DIR) + "/examples/tornado.iv"));
}

ScalarSplat& splatNode(sg::Separator& root) {
    return dynamic_cast<ScalarSplat&>(*root.child(root.childCount() - 1));
}

Rendered render(sg::Node& root, int size) {
    render::FrameAction action(size, size);
    const render::cpu::CpuRenderer renderer(2);
    image::Image image = renderer.draw(action.collect(root), action.statistics());
    return {std::move(image), action.statistics().splats};
}

// How much brighter column x is than the columns `kReach` to either side, in red, averaged over
// the rows [row, row + kBand): a seam is a narrow bright column over a run of rows.
constexpr int kReach = 4;
constexpr int kBand = 32;
float columnExcess(const image::Image& image, int x, int row) {
    float sum = 0.0f;
    for (int y = row; y < row + kBand; ++y) {
        sum += image.pixel(x, y).r -
               0.5f * (image.pixel(x - kReach, y).r + image.pixel(x + kReach, y).r);
    }
    return sum / static_cast<float>(kBand);
}

// The largest excess of a column of `budgeted` over the same column of `full`, within 8 columns
// of the middle where the seam was (6 px wide): elsewhere a coarse cut has structure of its own
// (level changes) that the full-resolution image lacks, which is blur, not a seam.
float seamAtMiddle(const image::Image& full, const image::Image& budgeted) {
    float largest = 0.0f;
    for (int row = 0; row + kBand <= kSize; row += kBand) {
        for (int x = kSize / 2 - 8; x < kSize / 2 + 8; ++x) {
            largest = std::max(largest,
                               columnExcess(budgeted, x, row) - columnExcess(full, x, row));
        }
    }
    return largest;
}

TEST(BudgetedRender, hasNoSeamDownTheSplitPlaneTheEyeLiesOn) {
    // Before the cut was drawn in centre-depth order, the traversal drew one side of the plane
    // wholly before the other and the overlapping kernels left a bright seam at every budget from
    // 10 000 splats up to all of them: +6.4 / 255 (10k) to +10.8 / 255 (all) in these linear
    // values (+3.5 to +6 in the 8-bit sRGB PNG); now at most +2.2 / 255. (A budget of all the
    // voxels or more draws them in slice order: one less is the finest cut.)
    const std::shared_ptr<sg::Separator> root = tornado();
    const Rendered full = render(*root, kSize);
    for (const int budget : {10000, 20000, 30000, static_cast<int>(full.splats) - 1}) {
        splatNode(*root).maxSplats.setValue(budget);
        const Rendered budgeted = render(*root, kSize);
        EXPECT_LE(budgeted.splats, static_cast<std::size_t>(budget));
        EXPECT_LT(seamAtMiddle(full.image, budgeted.image), 4.0f / 255.0f) << budget << " splats";
    }
}

TEST(BudgetedRender, aBudgetThatHoldsEveryVoxelDrawsTheFullResolutionImage) {
    const std::shared_ptr<sg::Separator> root = tornado();
    const Rendered full = render(*root, kSize);
    for (const std::size_t budget : {full.splats, full.splats + 1000}) {
        splatNode(*root).maxSplats.setValue(static_cast<std::int32_t>(budget));
        const Rendered budgeted = render(*root, kSize);
        EXPECT_EQ(budgeted.splats, full.splats) << budget;
        EXPECT_EQ(budgeted.image.pixels(), full.image.pixels()) << budget;
    }
    // One less: an octree cut within the budget.
    splatNode(*root).maxSplats.setValue(static_cast<std::int32_t>(full.splats) - 1);
    EXPECT_LE(render(*root, kSize).splats, full.splats - 1);
}

// How many of the frame's splats have their centre inside the image.
std::size_t splatsInTheImage(const render::Frame& frame) {
    std::size_t inside = 0;
    for (const render::FrameSplats& batch : frame.splats) {
        for (const octree::Splat& splat : batch.list()->splats()) {
            const glm::vec4 clip = batch.view.localToClip * glm::vec4(splat.position, 1.0f);
            inside += clip.w > 0.0f && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w;
        }
    }
    return inside;
}

TEST(BudgetedRender, aZoomedCutSpendsItsBudgetWhereTheImageIs) {
    // Zoomed 4 times into the tornado: nodes whose splats lie wholly outside the image are not
    // split, nor drawn, nor counted in the budget, so the budget refines what the image shows.
    // 61 % of the cut's 5000 splats have their centre in the image (the rest reach in from
    // outside); with the splits spread over the whole volume, 9 % had, and 37 % while the
    // children out of sight of nodes split in sight were drawn and counted.
    const std::shared_ptr<sg::Separator> root = tornado();
    auto& camera = dynamic_cast<PerspectiveCamera&>(*root->child(0));
    camera.heightAngle.setValue(camera.heightAngle.value() / 4.0f);
    splatNode(*root).maxSplats.setValue(5000);
    render::FrameAction action(kSize, kSize);
    const render::Frame frame = action.collect(*root);
    const std::size_t inside = splatsInTheImage(frame);
    EXPECT_GT(inside, action.statistics().splats / 2);
    EXPECT_GT(action.statistics().splats, 5000u - 7u) << "the budget is spent on what shows";
}

TEST(BudgetedRender, aZoomedFullFrameLeavesOutOnlySplatsThatCoverNoPixel) {
    const std::shared_ptr<sg::Separator> root = tornado();
    auto& camera = dynamic_cast<PerspectiveCamera&>(*root->child(0));
    camera.heightAngle.setValue(camera.heightAngle.value() / 4.0f);
    render::FrameAction action(kSize, kSize);
    render::Frame frame = action.collect(*root);
    ASSERT_EQ(frame.splats.size(), 1u);
    // Every voxel's splat, as the slice order walks them without the view's sides.
    const auto& transfer = dynamic_cast<const TransferFunction&>(*root->child(1));
    const auto& volume = dynamic_cast<const VolumeData&>(*root->child(2));
    auto every = std::make_shared<octree::SplatList>();
    octree::emitVoxelSplats(*transfer.classify(*volume.scalarGrid()),
                            frame.splats[0].view.octreeView(), *every);
    EXPECT_LT(frame.splats[0].splatCount(), every->size() * 3 / 4) << "blocks are left out";

    const render::cpu::CpuRenderer renderer(2);
    sg::RenderStatistics statistics;
    const image::Image sighted = renderer.draw(frame, statistics);
    frame.splats[0].voxels = nullptr; // the list of every voxel instead
    frame.splats[0].splats = every;
    EXPECT_EQ(renderer.draw(frame, statistics).pixels(), sighted.pixels());
}

TEST(BudgetedRender, splatsReachingIntoTheImageFromOutsideAreDrawn) {
    // Voxels 0 to 15 along x; the image's right edge at x = 6.6, so the block of voxels 8 to 15
    // lies wholly outside it, its nearest voxel 1.4 voxels out: the paper's kernel (support
    // 1.556) still reaches the last column of pixels (centres 0.0625 voxels inside). A reach
    // shorter than the footprint texture's (0.8 of it, 1.30 voxels) left the block out.
    registerNodeTypes();
    constexpr const char* kScene = R"(#Inventor V2.1 ascii
        Separator {
            OrthographicCamera { position 2.6 1.5 20 height 8 nearDistance 1 farDistance 40 }
            TransferFunction { rangeMode FIXED range 0 1 opacities [ 0.5, 0.5 ] }
        })";
    const auto root =
        std::dynamic_pointer_cast<sg::Separator>(sg::SceneReader::readString(kScene));
    const volume::GridGeometry geometry({16, 4, 4});
    auto volume = VolumeData::create();
    volume->setGrid(volume::ExternalScalarGrid::owning(geometry, std::vector<float>(256, 1.0f)));
    root->addChild(volume);
    root->addChild(TextureSplat::create());
    render::FrameAction action(64, 64);
    render::Frame frame = action.collect(*root);
    ASSERT_EQ(frame.splats.size(), 1u);
    const auto& transfer = dynamic_cast<const TransferFunction&>(*root->child(1));
    auto every = std::make_shared<octree::SplatList>();
    octree::emitVoxelSplats(*transfer.classify(*volume->scalarGrid()),
                            frame.splats[0].view.octreeView(), *every);
    ASSERT_EQ(every->size(), 256u);
    EXPECT_EQ(frame.splats[0].splatCount(), 256u) << "no block lies beyond the reach";

    const render::cpu::CpuRenderer renderer(1);
    sg::RenderStatistics statistics;
    const image::Image sighted = renderer.draw(frame, statistics);
    EXPECT_GT(sighted.pixel(63, 32).a, 0.0f) << "the block outside reaches the last column";
    frame.splats[0].voxels = nullptr; // the list of every voxel instead
    frame.splats[0].splats = every;
    EXPECT_EQ(renderer.draw(frame, statistics).pixels(), sighted.pixels());
}

TEST(BudgetedRender, aFullFrameAfterACutIsAFreshFullFrame) {
    // The node refills its last splat list: a full-resolution frame after a cut kept the cut's
    // coarse sizes on its voxel splats (the viewer's full-quality frame after any interaction).
    const std::shared_ptr<sg::Separator> root = tornado();
    const Rendered fresh = render(*tornado(), kSize);
    splatNode(*root).maxSplats.setValue(50000);
    render(*root, kSize);
    splatNode(*root).maxSplats.setValue(0);
    const Rendered after = render(*root, kSize);
    EXPECT_EQ(after.splats, fresh.splats);
    EXPECT_EQ(after.image.pixels(), fresh.image.pixels());
}

TEST(BudgetedRender, errorThresholdIsRelativeToTheLargestClassifiedValue) {
    const std::shared_ptr<sg::Separator> root = tornado();
    ScalarSplat& splat = splatNode(*root);
    const std::size_t everyVoxel = render(*root, 64).splats;
    std::vector<std::size_t> counts;
    for (const float threshold : {0.02f, 0.1f, 0.3f}) {
        splat.errorThreshold.setValue(threshold);
        counts.push_back(render(*root, 64).splats);
    }
    EXPECT_LT(counts[0], everyVoxel);
    EXPECT_GT(counts[0], counts[1]);
    EXPECT_GT(counts[1], counts[2]);

    // Ten times the opacity (and so the premultiplied colour): the same cuts.
    auto& transfer = dynamic_cast<TransferFunction&>(*root->child(1));
    std::vector<float> opacities = transfer.opacities.values();
    for (float& opacity : opacities) {
        opacity *= 10.0f;
    }
    transfer.opacities.setValue(opacities);
    std::size_t index = 0;
    for (const float threshold : {0.02f, 0.1f, 0.3f}) {
        splat.errorThreshold.setValue(threshold);
        EXPECT_EQ(render(*root, 64).splats, counts[index++]) << threshold;
    }
    splat.errorThreshold.setValue(0.0f);
    EXPECT_EQ(render(*root, 64).splats, everyVoxel) << "threshold 0 draws every voxel";
}

} // namespace
} // namespace texsplat::nodes
