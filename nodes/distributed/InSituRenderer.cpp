#include "nodes/distributed/InSituRenderer.h"

#include "nodes/VolumeData.h"
#include "nodes/distributed/RankAgreement.h"
#include "nodes/distributed/RankGrid.h"
#include "nodes/distributed/SplatPlacements.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::distributed {
namespace {

std::string vectorText(const glm::dvec3& value) {
    return std::to_string(value.x) + " " + std::to_string(value.y) + " " + std::to_string(value.z);
}

// The box of the whole grid that `block` holds (ghost cells included), checked to lie on the
// whole grid's voxels.
volume::IndexBox heldBox(const volume::GridGeometry& held, const volume::GridGeometry& whole) {
    const glm::dvec3 spacing = held.spacing();
    if (glm::any(glm::greaterThan(glm::abs(spacing - whole.spacing()),
                                  1e-9 * glm::abs(whole.spacing())))) {
        throw DataError("the block's spacing (" + vectorText(spacing) +
                        ") is not the whole grid's (" + vectorText(whole.spacing()) + ")");
    }
    const glm::dvec3 first = whole.worldToIndex(held.origin());
    const glm::dvec3 rounded = glm::round(first);
    if (glm::any(glm::greaterThan(glm::abs(first - rounded), glm::dvec3(1e-6)))) {
        throw DataError("the block's first voxel, at " + vectorText(held.origin()) +
                        ", is not a voxel of the whole grid (its origin " +
                        vectorText(whole.origin()) + " plus whole steps of its spacing)");
    }
    const glm::i64vec3 lo(rounded);
    return {lo, lo + held.dims()};
}

// The one VolumeData of source MEMORY of `scene`: where the blocks go.
nodes::VolumeData& memoryVolume(sg::Node& scene) {
    nodes::VolumeData* found = nullptr;
    int count = 0;
    for (nodes::VolumeData* volume : findVolumes(scene)) {
        if (volume->source.as<nodes::VolumeSource>() == nodes::VolumeSource::Memory) {
            found = volume;
            ++count;
        }
    }
    if (count != 1) {
        throw DataError("the scene has " + std::to_string(count) +
                        " VolumeData of source MEMORY; an in-situ render puts the blocks into "
                        "exactly one");
    }
    return *found;
}

} // namespace

InSituRenderer::InSituRenderer(MPI_Comm comm, const InSituOptions& options)
    : mComm(comm), mRenderer(comm, options.image, options.compositing) {}

std::optional<image::Image> InSituRenderer::render(const LocalBlock& block,
                                                   const volume::GridGeometry& whole,
                                                   const sg::Node::Ptr& scene,
                                                   const sg::Node::Ptr& camera) {
    // This rank's voxels: the block less its ghost cells, as its part of the whole grid.
    const volume::IndexBox owned = runAgreed(mComm, [&] {
        nodes::VolumeData& volume = memoryVolume(*scene);
        const bool holdsVoxels =
            std::visit([](const auto& grid) { return grid != nullptr; }, block.voxels);
        if (!holdsVoxels) {
            volume.setGrid(std::make_shared<const RankGrid<float>>(whole, nullptr, glm::i64vec3(0),
                                                                   volume::IndexBox{}));
            return volume::IndexBox{};
        }
        const volume::GridGeometry held =
            std::visit([](const auto& grid) { return grid->geometry(); }, block.voxels);
        const volume::IndexBox box = heldBox(held, whole);
        if (glm::any(glm::lessThan(block.ghostLow, glm::i64vec3(0))) ||
            glm::any(glm::lessThan(block.ghostHigh, glm::i64vec3(0))) ||
            glm::any(glm::greaterThan(block.ghostLow + block.ghostHigh, held.dims()))) {
            throw DataError("the block's ghost cells (low " +
                            volume::IndexBox{block.ghostLow, block.ghostHigh}.text() +
                            ") must be whole numbers >= 0 that leave it voxels");
        }
        const volume::IndexBox mine{box.lo + block.ghostLow, box.hi - block.ghostHigh};
        if (mine.intersection(volume::IndexBox::of(whole)) != mine) {
            throw DataError("the block's voxels " + mine.text() +
                            " (ghost cells left out) reach outside the whole grid's " +
                            volume::IndexBox::of(whole).text());
        }
        volume.setGrid(std::visit(
            [&](const auto& grid) -> volume::AnyGrid {
                using Value = typename std::decay_t<decltype(*grid)>::ValueType;
                return std::make_shared<const RankGrid<Value>>(whole, grid, box.lo, mine);
            },
            block.voxels));
        return mine;
    });
    // Every rank's box, for the blocks' visibility order.
    std::int64_t corners[6] = {owned.lo.x, owned.lo.y, owned.lo.z,
                               owned.hi.x, owned.hi.y, owned.hi.z};
    std::vector<std::int64_t> all(static_cast<std::size_t>(6 * mRenderer.size()));
    MPI_Allgather(corners, 6, MPI_INT64_T, all.data(), 6, MPI_INT64_T, mComm);
    std::vector<volume::IndexBox> bricks;
    for (std::size_t rank = 0; rank < all.size() / 6; ++rank) {
        const std::int64_t* box = &all[6 * rank];
        bricks.push_back({{box[0], box[1], box[2]}, {box[3], box[4], box[5]}});
    }
    runAgreed(mComm, [&] {
        mRenderer.setBricks(bricks);
        if (scene != mScene || camera != mCamera) {
            auto root = sg::Separator::create();
            root->addChild(camera);
            root->addChild(scene);
            mRoot = root;
            mScene = scene;
            mCamera = camera;
        }
    });
    return mRenderer.render(*mRoot);
}

std::optional<image::Image> render(MPI_Comm comm, const LocalBlock& block,
                                   const volume::GridGeometry& whole, const sg::Node::Ptr& scene,
                                   const sg::Node::Ptr& camera, const InSituOptions& options) {
    const auto renderer =
        runAgreed(comm, [&] { return std::make_unique<InSituRenderer>(comm, options); });
    return renderer->render(block, whole, scene, camera);
}

} // namespace texsplat::distributed
