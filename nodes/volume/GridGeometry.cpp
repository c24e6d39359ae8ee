#include "nodes/volume/GridGeometry.h"

#include "nodes/volume/detail/Format.h"
#include "scenegraph/Coordinates.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace texsplat::volume {
namespace {

std::string joined(const glm::i64vec3& v, const char* separator) {
    return std::to_string(v.x) + separator + std::to_string(v.y) + separator + std::to_string(v.z);
}

std::string joined(const glm::dvec3& v, const char* separator) {
    return detail::formatNumber(v.x) + separator + detail::formatNumber(v.y) + separator +
           detail::formatNumber(v.z);
}

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

GridGeometry::GridGeometry(const glm::i64vec3& dims, const glm::dvec3& origin,
                           const glm::dvec3& spacing)
    : mDims(dims), mOrigin(origin), mSpacing(spacing) {
    if (dims.x < 1 || dims.y < 1 || dims.z < 1)
        throw DataError("grid dimensions must be at least 1 voxel each, got " +
                        joined(dims, " x "));
    constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
    if (dims.x > kMax / dims.y || dims.x * dims.y > kMax / dims.z)
        throw DataError("grid of " + joined(dims, " x ") +
                        " voxels has more voxels than a 64-bit index can address");
    if (!isFinite(spacing) || spacing.x <= 0.0 || spacing.y <= 0.0 || spacing.z <= 0.0)
        throw DataError("grid spacing must be finite and positive, got " + joined(spacing, " "));
    if (!isFinite(origin))
        throw DataError("grid origin must be finite, got " + joined(origin, " "));
    const glm::dvec3 far = origin + glm::dvec3(dims) * spacing;
    const double largest = std::max({std::abs(origin.x), std::abs(origin.y), std::abs(origin.z),
                                     std::abs(far.x), std::abs(far.y), std::abs(far.z)});
    if (!(largest <= sg::kMaxCoordinate))
        throw DataError("grid spacing " + joined(spacing, " ") + " from origin " +
                        joined(origin, " ") + " puts voxels as far as " +
                        detail::formatNumber(largest) + ", beyond " +
                        detail::formatNumber(sg::kMaxCoordinate) +
                        ", the largest coordinate texsplat draws in single precision; give the "
                        "spacing in a larger length unit");
}

glm::i64vec3 GridGeometry::indexOf(std::int64_t linear) const {
    const std::int64_t slice = mDims.x * mDims.y;
    const std::int64_t k = linear / slice;
    const std::int64_t rest = linear - k * slice;
    return {rest % mDims.x, rest / mDims.x, k};
}

glm::i64vec3 GridGeometry::nearestIndex(const glm::dvec3& world) const {
    // Clamped so that positions far outside (or NaN) never overflow the integer conversion.
    constexpr double kLimit = 4.0e18;
    const glm::dvec3 index = glm::floor(worldToIndex(world) + 0.5);
    const glm::dvec3 safe = glm::clamp(glm::mix(index, glm::dvec3(0.0), glm::isnan(index)),
                                       glm::dvec3(-kLimit), glm::dvec3(kLimit));
    return glm::i64vec3(safe);
}

} // namespace texsplat::volume
