#include "nodes/distributed/BrickSurvey.h"

#include "nodes/ScalarSplat.h"
#include "nodes/VectorMarkSplat.h"
#include "nodes/VolumeData.h"
#include "nodes/elements/VolumeElement.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/SplatView.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Octree.h"
#include "octree/Refiner.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/ModelMatrixElement.h"

#include <array>
#include <mutex>

namespace texsplat::distributed {
namespace {

// Sets, for each non-empty voxel of `grid` (the brick at `offset` of a grid of `whole` voxels),
// the bits of its columns along x, y and z in the whole grid's planes.
void markColumns(const octree::ClassifiedGrid& grid, const glm::u64vec3& offset,
                 const glm::u64vec3& whole, SplatSurvey& survey) {
    const std::array<glm::u64vec2, 3> planes = {glm::u64vec2(whole.y, whole.z),
                                                glm::u64vec2(whole.x, whole.z),
                                                glm::u64vec2(whole.x, whole.y)};
    for (int axis = 0; axis < 3; ++axis) {
        survey.columns[static_cast<std::size_t>(axis)].assign(
            (planes[axis].x * planes[axis].y + 63) / 64, 0);
    }
    const auto set = [&](int axis, std::uint64_t first, std::uint64_t second) {
        const std::uint64_t bit = first + planes[static_cast<std::size_t>(axis)].x * second;
        survey.columns[static_cast<std::size_t>(axis)][bit / 64] |= std::uint64_t{1} << (bit % 64);
    };
    constexpr std::uint64_t kSize = octree::ClassifiedGrid::kBlockSize;
    const glm::u64vec3 dims = grid.dims();
    grid.forEachBlock([&](glm::u64vec3 block, octree::ClassifiedGrid::StorageIndex first) {
        std::array<glm::vec4, octree::ClassifiedGrid::kBlockVoxels> voxels;
        grid.readBlock(first, voxels);
        for (std::uint64_t slot = 0; slot < octree::ClassifiedGrid::kBlockVoxels; ++slot) {
            const glm::u64vec3 local =
                block * kSize +
                glm::u64vec3(slot % kSize, slot / kSize % kSize, slot / (kSize * kSize));
            if (glm::any(glm::greaterThanEqual(local, dims)) || voxels[slot] == glm::vec4(0.0f)) {
                continue;
            }
            const glm::u64vec3 voxel = local + offset;
            ++survey.voxels;
            set(0, voxel.y, voxel.z);
            set(1, voxel.x, voxel.z);
            set(2, voxel.x, voxel.y);
        }
    });
}

// Traverses a scene as a render does, surveying each splat node that needs the whole's figures.
class SurveyAction : public sg::Action {
public:
    explicit SurveyAction(float aspect) : sg::Action(methods()), mAspect(aspect) {}

    static sg::MethodTable& methods() {
        static sg::MethodTable table;
        static std::once_flag once;
        std::call_once(once, [] {
            table.add(nodes::ScalarSplat::classType(), [](sg::Action& action, sg::Node& node) {
                static_cast<SurveyAction&>(action).survey(static_cast<nodes::ScalarSplat&>(node));
            });
        });
        return table;
    }

    std::vector<SplatSurvey> surveys;

private:
    void survey(nodes::ScalarSplat& splat) {
        SplatSurvey result;
        result.splat = &splat;
        result.drawsMarks = dynamic_cast<nodes::VectorMarkSplat*>(&splat) != nullptr;
        result.cuts = splat.errorThreshold.value() > 0.0f || splat.maxSplats.value() > 0;
        if (result.drawsMarks) {
            const std::shared_ptr<const octree::ClassifiedGrid> grid = splat.classifiedGrid(*this);
            const nodes::VolumeData& volume = *state().get<nodes::VolumeElement>().volume;
            const volume::IndexBox brick = volume.brick().value_or(volume::IndexBox{});
            const volume::GridGeometry whole = volume.wholeGeometry();
            result.offset = glm::u64vec3(brick.isEmpty() ? glm::i64vec3(0) : brick.lo);
            markColumns(*grid, result.offset, glm::u64vec3(whole.dims()), result);
            result.spacing = grid->spacing();
            result.wholeCentre = whole.indexToWorld((glm::dvec3(whole.dims()) - 1.0) * 0.5);
            result.wholeLow = whole.indexToWorld(glm::dvec3(-0.5));
            result.wholeHigh = whole.indexToWorld(glm::dvec3(whole.dims()) - 0.5);
        }
        if (result.cuts && splat.classifiedGrid(*this)->nonEmptyVoxelCount() > 0) {
            const octree::Octree& tree = splat.octree(*this);
            result.valueScale = tree.valueScale();
            const render::CameraView camera = render::CameraView::current(state(), splat, mAspect);
            const render::SplatView view = render::SplatView::fromMatrices(
                state().get<sg::ModelMatrixElement>().matrix, camera.view, camera.projection,
                glm::vec3(tree.grid().spacing()));
            result.refiner = std::make_shared<const octree::Refiner>(
                tree, view.refinementView(splat.splatReach()));
            result.largestPriority = result.refiner->priority(tree.root());
        }
        surveys.push_back(std::move(result));
    }

    float mAspect;
};

} // namespace

std::uint64_t cutSize(const SplatSurvey& survey, double threshold, std::uint64_t limit) {
    if (!survey.refiner) {
        return 0;
    }
    const octree::Octree& tree = survey.refiner->cut().octree();
    std::vector<octree::NodeRef> stack{tree.root()};
    std::array<octree::NodeRef, 8> children;
    std::uint64_t splats = 0;
    while (!stack.empty() && splats <= limit) {
        const octree::NodeRef node = stack.back();
        stack.pop_back();
        const int count = node.level > 0 && survey.refiner->priority(node) > threshold
                              ? tree.children(node, children)
                              : 0;
        if (count == 0) {
            ++splats;
        }
        stack.insert(stack.end(), children.begin(), children.begin() + count);
    }
    return splats;
}

std::vector<SplatSurvey> surveyBricks(sg::Node& root, float aspect) {
    SurveyAction action(aspect);
    action.apply(root);
    return std::move(action.surveys);
}

} // namespace texsplat::distributed
