#include "DistributedTesting.h"

#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/distributed/InSituRenderer.h"
#include "nodes/render/CameraView.h"
#include "nodes/volume/ExternalGrid.h"
#include "scenegraph/Box3.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace texsplat::test {
namespace {

constexpr std::int64_t kSize = 28;

const volume::GridGeometry kWhole({kSize, kSize + 3, kSize - 2}, glm::dvec3(-1.0),
                                  glm::dvec3(2.0 / double(kSize - 1)));

float field(const glm::dvec3& p) {
    return static_cast<float>(std::exp(-3.0 * glm::dot(p, p)) +
                              0.2 * std::sin(5.0 * p.x) * std::cos(4.0 * p.y + p.z));
}

// The simulation's blocks: a grid of blocks along y and z (the slicing axis is x), each holding
// `ghost` layers of its neighbours' voxels; from 3 ranks on, the last rank owns nothing.
struct Block {
    volume::IndexBox held;
    glm::i64vec3 ghostLow{0};
    glm::i64vec3 ghostHigh{0};
    std::vector<float> values;
};

Block blockOf(int rank, int ranks, std::int64_t ghost) {
    const int blocks = ranks >= 3 ? ranks - 1 : ranks;
    const int alongY = blocks % 2 == 0 && blocks >= 4 ? 2 : 1;
    const int alongZ = blocks / alongY;
    const glm::i64vec3 dims = kWhole.dims();
    Block block;
    const int coordinates[3] = {0, rank % alongY, rank / alongY};
    const int counts[3] = {1, alongY, alongZ};
    for (int axis = 0; axis < 3; ++axis) {
        const std::int64_t lo = std::min(dims[axis], dims[axis] * coordinates[axis] / counts[axis]);
        const std::int64_t hi =
            std::min(dims[axis], dims[axis] * (coordinates[axis] + 1) / counts[axis]);
        block.held.lo[axis] = std::max<std::int64_t>(0, lo - ghost);
        block.held.hi[axis] = std::min<std::int64_t>(dims[axis], hi + ghost);
        block.ghostLow[axis] = lo - block.held.lo[axis];
        block.ghostHigh[axis] = block.held.hi[axis] - hi;
    }
    if (rank >= alongY * alongZ || block.held.isEmpty()) {
        block.held = {};
    }
    const glm::i64vec3 size = block.held.dims();
    glm::i64vec3 index;
    for (index.z = 0; index.z < size.z; ++index.z)
        for (index.y = 0; index.y < size.y; ++index.y)
            for (index.x = 0; index.x < size.x; ++index.x)
                block.values.push_back(
                    field(kWhole.indexToWorld(glm::dvec3(block.held.lo + index))));
    return block;
}

sg::Node::Ptr makeScene() {
    auto scene = sg::Separator::create();
    auto transfer = nodes::TransferFunction::create();
    transfer->opacityValues.setValue({0.0f, 0.3f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.0f, 8.0f});
    scene->addChild(transfer);
    auto data = nodes::VolumeData::create();
    data->source.setValue(nodes::VolumeSource::Memory);
    scene->addChild(data);
    scene->addChild(nodes::TextureSplat::create());
    return scene;
}

sg::Node::Ptr makeCamera() {
    auto camera = nodes::PerspectiveCamera::create();
    camera->orientation.setValue(render::rotationLookingAlong({-1.0f, -0.5f, -0.3f}));
    camera->viewAll(sg::Box3(glm::vec3(kWhole.boundsMin()), glm::vec3(kWhole.boundsMax())), 1.0f);
    return camera;
}

// The PSNR, on rank 0, of the in-situ picture of the blocks with `ghost` layers against the
// whole grid's in one process.
double inSituPsnr(std::int64_t ghost) {
    Block block = blockOf(rank(), ranks(), ghost);
    distributed::LocalBlock local; // a rank that owns nothing gives no voxels
    if (!block.held.isEmpty()) {
        local.voxels = std::make_shared<volume::ExternalScalarGrid>(
            volume::boxGeometry(kWhole, block.held), block.values.data(), block.values.size());
        local.ghostLow = block.ghostLow;
        local.ghostHigh = block.ghostHigh;
    }
    distributed::InSituOptions options;
    options.image = testImage();
    const sg::Node::Ptr camera = makeCamera();
    const std::optional<image::Image> picture =
        distributed::render(MPI_COMM_WORLD, local, kWhole, makeScene(), camera, options);
    if (rank() != 0) {
        return 0.0;
    }
    std::vector<float> values;
    glm::i64vec3 index;
    for (index.z = 0; index.z < kWhole.dims().z; ++index.z)
        for (index.y = 0; index.y < kWhole.dims().y; ++index.y)
            for (index.x = 0; index.x < kWhole.dims().x; ++index.x)
                values.push_back(field(kWhole.indexToWorld(glm::dvec3(index))));
    const sg::Node::Ptr scene = makeScene();
    static_cast<nodes::VolumeData&>(*static_cast<sg::Separator&>(*scene).child(1))
        .setGrid(
            std::make_shared<volume::ExternalScalarGrid>(kWhole, values.data(), values.size()));
    auto root = sg::Separator::create();
    root->addChild(camera);
    root->addChild(scene);
    render::SceneRenderer alone(testImage());
    return image::ImageComparison(alone.render(*root), *picture).rgb().psnr;
}

// The message of the DataError that rendering `local` in situ throws on this rank.
std::string inSituRefusal(const distributed::LocalBlock& local) {
    distributed::InSituOptions options;
    options.image = testImage();
    try {
        distributed::render(MPI_COMM_WORLD, local, kWhole, makeScene(), makeCamera(), options);
    } catch (const DataError& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected DataError";
    return {};
}

TEST(InSitu, givesTheOneProcessPictureOfBlocksWithOrWithoutGhostCells) {
    // Each voxel is drawn by the rank that owns it, its whole footprint: no ghost layer is too
    // thin, and none shows.
    for (const std::int64_t ghost : {0, 1, 3}) {
        const double psnr = inSituPsnr(ghost);
        if (rank() == 0) {
            EXPECT_GE(psnr, kMinimumPsnr) << ghost << " ghost layers, " << ranks() << " ranks";
        }
    }
}

TEST(InSitu, refusesBlocksWhoseGhostCellsAreNotDeclared) {
    if (ranks() < 2) {
        return;
    }
    // Two layers of ghost cells held, none declared: the blocks overlap.
    Block block = blockOf(rank(), ranks(), 2);
    distributed::LocalBlock local;
    if (!block.held.isEmpty()) {
        local.voxels = std::make_shared<volume::ExternalScalarGrid>(
            volume::boxGeometry(kWhole, block.held), block.values.data(), block.values.size());
    }
    const std::string refusal = inSituRefusal(local);
    EXPECT_NE(refusal.find("overlap"), std::string::npos) << refusal;
    EXPECT_NE(refusal.find("leave ghost cells out"), std::string::npos);
}

TEST(InSitu, refusesABlockOffTheWholeGridsVoxels) {
    std::vector<float> values(8, 1.0f);
    distributed::LocalBlock local;
    // Half a voxel off: not a voxel of the whole grid.
    local.voxels = std::make_shared<volume::ExternalScalarGrid>(
        volume::GridGeometry({2, 2, 2}, kWhole.origin() + 0.5 * kWhole.spacing(), kWhole.spacing()),
        values.data(), values.size());
    const std::string refusal = inSituRefusal(local);
    EXPECT_NE(refusal.find("is not a voxel of the whole grid"), std::string::npos) << refusal;
}

} // namespace
} // namespace texsplat::test
