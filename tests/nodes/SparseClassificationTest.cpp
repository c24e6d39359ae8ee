// Sparse end to end (issue 13): what classification and splatting cost follows the voxels the
// transfer function leaves visible, not the grid's box; dense and sparse storage of the same
// data, and the same data in a larger empty box, give the same image bit for bit.
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/SparseGrid.h"

#include "nodes/NodeTypes.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/Frame.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/SceneImage.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Octree.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "octree/View.h"
#include "scenegraph/Separator.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace texsplat::nodes {
namespace {

constexpr std::int64_t kSmallBox = 64;
constexpr std::int64_t kLargeBox = 1024;
// Where the blob's box starts in the large grid: a multiple of the block size, so that the
// blob covers the same blocks in both.
constexpr std::int64_t kShift = 512;

// A ball of radius 11 voxels around voxel (30, 33, 28) of the small box, brighter inwards,
// stored into `grid` at `offset`.
template <class Grid> void addBlob(Grid& grid, std::int64_t offset) {
    const glm::dvec3 centre(30.0, 33.0, 28.0);
    for (std::int64_t z = 16; z < 42; ++z)
        for (std::int64_t y = 20; y < 47; ++y)
            for (std::int64_t x = 17; x < 44; ++x) {
                const double r = glm::length(glm::dvec3(x, y, z) - centre) / 11.0;
                if (r < 1.0) {
                    grid.setValue(glm::i64vec3(x, y, z) + offset, static_cast<float>(1.0 - r));
                }
            }
}

std::shared_ptr<volume::SparseScalarGrid> sparseBlob(std::int64_t box, std::int64_t offset,
                                                     glm::dvec3 origin = glm::dvec3(0.0)) {
    auto grid = std::make_shared<volume::SparseScalarGrid>(
        volume::GridGeometry(glm::i64vec3(box), origin));
    addBlob(*grid, offset);
    return grid;
}

TransferFunction::Ptr transferFunction() {
    auto transfer = TransferFunction::create();
    transfer->rangeMode.setValue(RangeMode::Fixed);
    transfer->range.setValue(glm::vec2(0.0f, 1.0f));
    transfer->opacities.setValue({0.0f, 2.0f});
    return transfer;
}

class SparseClassification : public ::testing::Test {
protected:
    void SetUp() override { registerNodeTypes(); }
};

TEST_F(SparseClassification, classifiedBytesFollowTheVisibleVoxelsNotTheBox) {
    const auto transfer = transferFunction();
    const auto small = transfer->classify(*sparseBlob(kSmallBox, 0));
    const auto large = transfer->classify(*sparseBlob(kLargeBox, kShift));
    ASSERT_GT(small->blockCount(), 0u);
    EXPECT_EQ(large->blockCount(), small->blockCount());
    // The large grid pays only its block table (4 bytes per 512 voxels of the box) more.
    const std::uint64_t tables =
        (octree::ClassifiedGrid::boxBlockCount(glm::u64vec3(kLargeBox)) -
         octree::ClassifiedGrid::boxBlockCount(glm::u64vec3(kSmallBox))) *
        sizeof(std::uint32_t);
    EXPECT_EQ(large->memoryBytes() - small->memoryBytes(), tables);
    // ... and the octree over it has as many records.
    EXPECT_EQ(octree::Octree(large).nodes().size() - octree::Octree(small).nodes().size(),
              4u); // the large tree's four levels above the small one's root
}

TEST_F(SparseClassification, aTransparentTransferFunctionAllocatesNoVoxelsAndNoSplats) {
    auto transfer = transferFunction();
    transfer->opacities.setValue({0.0f, 0.0f});
    const auto classified = transfer->classify(*sparseBlob(kLargeBox, kShift));
    EXPECT_EQ(classified->blockCount(), 0u);
    EXPECT_EQ(classified->memoryBytes(),
              octree::ClassifiedGrid::memoryBytesFor(classified->dims(), 0, false,
                                                     TransferFunction::kLevels + 1));
    octree::SplatList splats;
    octree::emitVoxelSplats(*classified, octree::View::orthographic({0.2, -0.3, -1.0}), splats);
    EXPECT_EQ(splats.size(), 0u);
    EXPECT_TRUE(octree::Octree(classified).isEmpty());
}

// The scene `grid` makes with a fixed camera (framing would follow the box) looking at the blob
// from an oblique direction, from inside the large box.
image::Image renderWithFixedCamera(const volume::ScalarGridPtr& grid) {
    auto data = VolumeData::create();
    data->setGrid(grid);
    auto camera = PerspectiveCamera::create();
    camera->position.setValue(glm::vec3(75.0f, 60.0f, 90.0f));
    camera->orientation.setValue(
        render::rotationLookingAlong(glm::vec3(30.0f, 33.0f, 28.0f) - camera->position.value()));
    camera->nearDistance.setValue(1.0f);
    camera->farDistance.setValue(400.0f);
    camera->heightAngle.setValue(0.5f);
    auto scene = sg::Separator::create();
    scene->addChild(camera);
    scene->addChild(data);
    scene->addChild(transferFunction());
    scene->addChild(TextureSplat::create());
    return render::sceneImage(scene, {96, 80, glm::vec4(0.0f), 2});
}

void expectSameImage(const image::Image& a, const image::Image& b) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    int differing = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            differing += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    EXPECT_EQ(differing, 0);
}

TEST_F(SparseClassification, denseSparseAndALargerBoxGiveTheSameImage) {
    auto dense = std::make_shared<volume::DenseScalarGrid>(
        volume::GridGeometry(glm::i64vec3(kSmallBox)));
    addBlob(*dense, 0);
    const image::Image fromDense = renderWithFixedCamera(dense);
    float alpha = 0.0f;
    for (int y = 0; y < fromDense.height(); ++y)
        for (int x = 0; x < fromDense.width(); ++x)
            alpha += fromDense.pixel(x, y).a;
    EXPECT_GT(alpha, 100.0f); // the blob is in view
    expectSameImage(renderWithFixedCamera(sparseBlob(kSmallBox, 0)), fromDense);
    // The blob at the same place in the world, inside a box of 1024³ voxels.
    expectSameImage(renderWithFixedCamera(sparseBlob(kLargeBox, kShift, glm::dvec3(-kShift))),
                    fromDense);
}

// A CPU frame of the blob at full resolution, or with a splat budget: its memory counters.
sg::FrameMemory frameMemory(int maxSplats) {
    auto data = VolumeData::create();
    data->setGrid(volume::ScalarGridPtr(sparseBlob(kSmallBox, 0)));
    auto splat = TextureSplat::create();
    splat->maxSplats.setValue(maxSplats);
    auto scene = sg::Separator::create();
    scene->addChild(data);
    scene->addChild(transferFunction());
    scene->addChild(splat);
    render::FrameAction action(32, 32);
    const render::Frame& frame = action.collect(*render::framedScene(scene, 1.0f));
    EXPECT_EQ(frame.splats.size(), 1u);
    return action.statistics().memory;
}

TEST_F(SparseClassification, aFrameCountsOnlyWhatItMakes) {
    const sg::FrameMemory full = frameMemory(0);
    EXPECT_EQ(full.grids, sparseBlob(kSmallBox, 0)->memoryBytes());
    EXPECT_GT(full.classified, 0u);
    EXPECT_EQ(full.octree, 0u);   // full resolution needs no octree
    EXPECT_EQ(full.textures, 0u); // the CPU backend makes no GL texture
    EXPECT_EQ(full.splats, 0u);   // every voxel, drawn from the grid without a list
    const sg::FrameMemory budgeted = frameMemory(500);
    EXPECT_GT(budgeted.octree, 0u);
    EXPECT_GE(budgeted.splats, 400u * sizeof(octree::Splat)); // the cut's list
}

} // namespace
} // namespace texsplat::nodes
