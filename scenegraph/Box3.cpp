#include "scenegraph/Box3.h"

#include <limits>

namespace texsplat::sg {

Box3::Box3()
    : mMin(std::numeric_limits<float>::infinity()), mMax(-std::numeric_limits<float>::infinity()) {}

Box3::Box3(const glm::vec3& min, const glm::vec3& max) : mMin(min), mMax(max) {}

glm::vec3 Box3::size() const { return isEmpty() ? glm::vec3(0.0f) : mMax - mMin; }

void Box3::extendBy(const glm::vec3& point) {
    mMin = glm::min(mMin, point);
    mMax = glm::max(mMax, point);
}

void Box3::extendBy(const Box3& box) {
    if (!box.isEmpty()) {
        extendBy(box.mMin);
        extendBy(box.mMax);
    }
}

glm::vec3 Box3::corner(int index) const {
    return {(index & 1) != 0 ? mMax.x : mMin.x, (index & 2) != 0 ? mMax.y : mMin.y,
            (index & 4) != 0 ? mMax.z : mMin.z};
}

Box3 Box3::transformed(const glm::mat4& matrix) const {
    Box3 result;
    if (isEmpty()) {
        return result;
    }
    for (int index = 0; index < 8; ++index) {
        result.extendBy(glm::vec3(matrix * glm::vec4(corner(index), 1.0f)));
    }
    return result;
}

bool Box3::operator==(const Box3& other) const {
    return (isEmpty() && other.isEmpty()) || (mMin == other.mMin && mMax == other.mMax);
}

} // namespace texsplat::sg
