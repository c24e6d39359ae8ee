#include "octree/ClassifiedGrid.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace texsplat::octree {

namespace {

std::string dimsText(glm::u64vec3 dims) {
    std::ostringstream text;
    text << dims.x << "x" << dims.y << "x" << dims.z;
    return text.str();
}

std::string vectorText(glm::dvec3 v) {
    std::ostringstream text;
    text << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return text.str();
}

bool isFinite(glm::dvec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

ClassifiedGrid::ClassifiedGrid(glm::u64vec3 dims, glm::dvec3 spacing, glm::dvec3 origin)
    : mDims(dims), mSpacing(spacing), mOrigin(origin) {
    if (dims.x == 0 || dims.y == 0 || dims.z == 0) {
        throw DataError("ClassifiedGrid: dimensions must be positive, got " + dimsText(dims));
    }
    // The voxels live in one std::vector, so their byte count must fit in size_t.
    constexpr std::uint64_t kMaxVoxels =
        std::numeric_limits<std::size_t>::max() / sizeof(glm::vec4);
    if (dims.y > kMaxVoxels / dims.x || dims.z > kMaxVoxels / (dims.x * dims.y)) {
        throw DataError("ClassifiedGrid: " + dimsText(dims) +
                        " voxels exceed the addressable memory");
    }
    if (!isFinite(spacing) || spacing.x <= 0.0 || spacing.y <= 0.0 || spacing.z <= 0.0) {
        throw DataError("ClassifiedGrid: spacing must be finite and positive, got " +
                        vectorText(spacing));
    }
    if (!isFinite(origin)) {
        throw DataError("ClassifiedGrid: origin must be finite, got " + vectorText(origin));
    }
    mVoxels.assign(static_cast<std::size_t>(voxelCount()), glm::vec4(0.0f));
}

void ClassifiedGrid::setVoxel(glm::u64vec3 ijk, glm::vec3 color, float extinction) {
    TEXSPLAT_ASSERT(ijk.x < mDims.x && ijk.y < mDims.y && ijk.z < mDims.z,
                    "ClassifiedGrid::setVoxel(): voxel outside the grid");
    const glm::vec4 value(color, extinction);
    for (int channel = 0; channel < 4; ++channel) {
        if (!std::isfinite(value[channel]) || value[channel] < 0.0f) {
            std::ostringstream text;
            text << "ClassifiedGrid: voxel (" << ijk.x << ", " << ijk.y << ", " << ijk.z
                 << "): " << (channel < 3 ? "color" : "extinction")
                 << " must be finite and >= 0, got " << value[channel];
            throw DataError(text.str());
        }
    }
    mVoxels[static_cast<std::size_t>(index(ijk))] = value;
}

void ClassifiedGrid::enableVectors() {
    if (mVectors.empty()) {
        mVectors.assign(mVoxels.size(), glm::vec3(0.0f));
    }
}

void ClassifiedGrid::setVector(glm::u64vec3 ijk, glm::vec3 vector) {
    TEXSPLAT_ASSERT(hasVectors(), "ClassifiedGrid::setVector(): enableVectors() first");
    TEXSPLAT_ASSERT(ijk.x < mDims.x && ijk.y < mDims.y && ijk.z < mDims.z,
                    "ClassifiedGrid::setVector(): voxel outside the grid");
    if (!isFinite(glm::dvec3(vector))) {
        std::ostringstream text;
        text << "ClassifiedGrid: voxel (" << ijk.x << ", " << ijk.y << ", " << ijk.z
             << "): vector must be finite, got " << vectorText(glm::dvec3(vector));
        throw DataError(text.str());
    }
    mVectors[static_cast<std::size_t>(index(ijk))] = vector;
}

} // namespace texsplat::octree
