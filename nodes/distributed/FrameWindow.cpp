#include "nodes/distributed/FrameWindow.h"

#include "nodes/render/MarkDrawing.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Splat.h"
#include "octree/VoxelSplats.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace texsplat::distributed {
namespace {

// Pixels around a batch's projected box: rounding, and for marks their least size on screen
// whatever their voxels': a mark at least two least half-lengths long travels up to half its
// length from where it was emitted (render::makeScreenMarks()), so its far end reaches a whole
// least length away, and half a least width beside.
constexpr double kRoundingPixels = 2.0;
constexpr double kMarkPixels = 2.0 * double(render::MarkDrawing::kMinHalfLengthPixels) +
                               double(render::MarkDrawing::kMinHalfWidthPixels) + kRoundingPixels;

// A region of pixels, as doubles while it grows.
struct PixelBox {
    double x0 = std::numeric_limits<double>::infinity();
    double y0 = std::numeric_limits<double>::infinity();
    double x1 = -std::numeric_limits<double>::infinity();
    double y1 = -std::numeric_limits<double>::infinity();
    bool isWholeImage = false;
};

// Grows `low` and `high` to hold the centres of the splats of `batch` (local space) and returns
// the largest splat size; a batch of voxels, which holds no list, by its allocated blocks'
// voxels (a bound: empty voxels among them make no splat).
double addCentres(const render::FrameSplats& batch, glm::dvec3& low, glm::dvec3& high) {
    if (batch.voxels) {
        const octree::ClassifiedGrid& grid = batch.voxels->grid();
        constexpr std::uint64_t kSize = octree::ClassifiedGrid::kBlockSize;
        grid.forEachBlock([&](glm::u64vec3 block, octree::ClassifiedGrid::StorageIndex) {
            const glm::u64vec3 first = block * kSize;
            const glm::u64vec3 last = glm::min(first + kSize, grid.dims()) - glm::u64vec3(1);
            for (const glm::u64vec3& corner : {first, last}) {
                const glm::dvec3 centre(glm::vec3(grid.toWorld(glm::dvec3(corner))));
                low = glm::min(low, centre);
                high = glm::max(high, centre);
            }
        });
        return grid.blockCount() > 0 ? 1.0 : 0.0;
    }
    double largest = 0.0;
    for (const octree::Splat& splat : batch.splats->splats()) {
        low = glm::min(low, glm::dvec3(splat.position));
        high = glm::max(high, glm::dvec3(splat.position));
        largest = std::max(largest, double(splat.size));
    }
    return largest;
}

// Grows `box` by the splats of `batch` in an image of width x height.
void addBatch(const render::FrameSplats& batch, int width, int height, PixelBox& box) {
    if (batch.splatCount() == 0) {
        return;
    }
    glm::dvec3 low(std::numeric_limits<double>::infinity());
    glm::dvec3 high(-std::numeric_limits<double>::infinity());
    const double largest = addCentres(batch, low, high);
    const glm::dvec3 spacing(batch.view.spacing);
    const double reach =
        largest * batch.footprint->reach() * std::max({spacing.x, spacing.y, spacing.z});
    low -= reach;
    high += reach;
    const double margin = batch.footprint->hasMarks() ? kMarkPixels : kRoundingPixels;
    const glm::dmat4 localToClip(batch.view.localToClip);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec4 local((corner & 1) ? high.x : low.x, (corner & 2) ? high.y : low.y,
                               (corner & 4) ? high.z : low.z, 1.0);
        const glm::dvec4 clip = localToClip * local;
        if (!(clip.w > 1e-9)) {
            box.isWholeImage = true; // reaches to or behind the eye plane
            return;
        }
        const double x = (clip.x / clip.w * 0.5 + 0.5) * width;
        const double y = (0.5 - clip.y / clip.w * 0.5) * height;
        box.x0 = std::min(box.x0, x - margin);
        box.x1 = std::max(box.x1, x + margin);
        box.y0 = std::min(box.y0, y - margin);
        box.y1 = std::max(box.y1, y + margin);
    }
}

} // namespace

image::ImageRegion splatFootprint(const render::Frame& frame) {
    PixelBox box;
    for (const render::FrameSplats& batch : frame.splats) {
        addBatch(batch, frame.width, frame.height, box);
        if (box.isWholeImage) {
            return {0, 0, frame.width, frame.height};
        }
    }
    if (!(box.x0 < box.x1) || !(box.y0 < box.y1)) {
        return {};
    }
    const auto clampTo = [](double value, int limit) {
        return static_cast<int>(std::clamp(value, 0.0, double(limit)));
    };
    const int x0 = clampTo(std::floor(box.x0), frame.width);
    const int y0 = clampTo(std::floor(box.y0), frame.height);
    const int x1 = clampTo(std::ceil(box.x1), frame.width);
    const int y1 = clampTo(std::ceil(box.y1), frame.height);
    if (x1 <= x0 || y1 <= y0) {
        return {};
    }
    return {x0, y0, x1 - x0, y1 - y0};
}

void cropFrame(render::Frame& frame, const image::ImageRegion& region) {
    const double width = frame.width;
    const double height = frame.height;
    // Normalized device coordinates of the region's centre, and how much larger it becomes.
    const double centreX = (2.0 * region.x + region.width) / width - 1.0;
    const double centreY = 1.0 - (2.0 * region.y + region.height) / height;
    const double scaleX = width / region.width;
    const double scaleY = height / region.height;
    glm::dmat4 crop(1.0);
    crop[0][0] = scaleX;
    crop[1][1] = scaleY;
    crop[3][0] = -centreX * scaleX;
    crop[3][1] = -centreY * scaleY;
    const auto cropped = [&](const glm::mat4& localToClip) {
        return glm::mat4(crop * glm::dmat4(localToClip));
    };
    for (render::FrameSplats& batch : frame.splats) {
        batch.view.localToClip = cropped(batch.view.localToClip);
    }
    for (render::FrameMesh& mesh : frame.meshes) {
        mesh.lighting.localToClip = cropped(mesh.lighting.localToClip);
    }
    frame.width = region.width;
    frame.height = region.height;
}

} // namespace texsplat::distributed
