#include "octree/View.h"

#include "scenegraph/Error.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace texsplat::octree {

namespace {

std::string vectorText(glm::dvec3 v) {
    std::ostringstream text;
    text << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return text.str();
}

bool isFinite(glm::dvec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::dvec3 checkedDirection(glm::dvec3 direction) {
    // Scaling by the largest component first keeps huge and denormal directions normalizable.
    const glm::dvec3 magnitude = glm::abs(direction);
    const double largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    if (!isFinite(direction) || !(largest > 0.0)) {
        throw DataError("View: direction must be finite and non-zero, got " +
                        vectorText(direction));
    }
    return glm::normalize(direction / largest);
}

} // namespace

View::View(Projection projection, glm::dvec3 direction, glm::dvec3 eye)
    : mProjection(projection), mDirection(direction), mEye(eye) {}

View View::orthographic(glm::dvec3 direction) {
    return View(Projection::Orthographic, checkedDirection(direction), glm::dvec3(0.0));
}

View View::perspective(glm::dvec3 eye, glm::dvec3 direction) {
    if (!isFinite(eye)) {
        throw DataError("View: eye must be finite, got " + vectorText(eye));
    }
    return View(Projection::Perspective, checkedDirection(direction), eye);
}

View View::seeingOnly(const Sides& sides, double reach) const {
    if (!std::isfinite(reach) || reach < 0.0) {
        throw DataError("View: a splat's reach must be finite and >= 0, got " +
                        std::to_string(reach));
    }
    View result = *this;
    result.mHasSides = true;
    result.mSides = sides;
    result.mReach = reach;
    return result;
}

bool View::isOutOfSight(glm::dvec3 low, glm::dvec3 high) const {
    const glm::dvec3 extent = high - low;
    return isOutOfSight(low, high, std::max({extent.x, extent.y, extent.z}),
                        0.5 * std::min({extent.x, extent.y, extent.z}));
}

bool View::isSubtreeOutOfSight(glm::dvec3 low, glm::dvec3 high) const {
    const glm::dvec3 extent = high - low;
    return isOutOfSight(low, high, std::max({extent.x, extent.y, extent.z}), 0.0);
}

bool View::isOutOfSight(glm::dvec3 low, glm::dvec3 high, double nodeEdge,
                        double nodeHalfWidth) const {
    if (!mHasSides) {
        return false;
    }
    const double reach = mReach * nodeEdge;
    const double margin = reach - std::min(nodeHalfWidth, 0.5 * reach);
    const glm::dvec3 widenedLow = low - margin;
    const glm::dvec3 widenedHigh = high + margin;
    for (const glm::dvec4& side : mSides) {
        // The corner of the widened box farthest to the inner side; NaN compares false.
        const glm::dvec3 inner(side.x >= 0.0 ? widenedHigh.x : widenedLow.x,
                               side.y >= 0.0 ? widenedHigh.y : widenedLow.y,
                               side.z >= 0.0 ? widenedHigh.z : widenedLow.z);
        if (glm::dot(glm::dvec3(side), inner) + side.w < 0.0) {
            return true;
        }
    }
    return false;
}

bool View::isWhollyInSight(glm::dvec3 low, glm::dvec3 high) const {
    if (!mHasSides) {
        return true;
    }
    for (const glm::dvec4& side : mSides) {
        // The corner of the box farthest to the outer side; NaN compares false (not inside).
        const glm::dvec3 outer(side.x >= 0.0 ? low.x : high.x, side.y >= 0.0 ? low.y : high.y,
                               side.z >= 0.0 ? low.z : high.z);
        if (!(glm::dot(glm::dvec3(side), outer) + side.w >= 0.0)) {
            return false;
        }
    }
    return true;
}

glm::dvec3 View::farthestCorner(glm::dvec3 low, glm::dvec3 high) const {
    // Per axis, the upper face when the direction's component is positive.
    return {mDirection.x > 0.0 ? high.x : low.x, mDirection.y > 0.0 ? high.y : low.y,
            mDirection.z > 0.0 ? high.z : low.z};
}

bool View::isBoxBehindEye(glm::dvec3 low, glm::dvec3 high) const {
    return isPerspective() && depth(farthestCorner(low, high)) <= 0.0;
}

bool View::isBoxInFrontOfEye(glm::dvec3 low, glm::dvec3 high) const {
    if (!isPerspective()) {
        return true;
    }
    // The nearest corner is the farthest one of the box turned around: low and high swapped.
    const double margin = 1e-9 * (glm::length(high - low) + glm::length(mEye - low));
    return depth(farthestCorner(high, low)) > margin;
}

} // namespace texsplat::octree
