#pragma once

#include "nodes/detail/NodeContext.h"
#include "scenegraph/Error.h"
#include "scenegraph/Rotation.h"

#include <glm/glm.hpp>

#include <cmath>

namespace texsplat::nodes::detail {

/// @brief Whether every component of `vector` is finite (no NaN, no infinity).
template <glm::length_t L, class T, glm::qualifier Q>
bool isFinite(const glm::vec<L, T, Q>& vector) {
    for (glm::length_t i = 0; i < L; ++i) {
        if (!std::isfinite(vector[i])) {
            return false;
        }
    }
    return true;
}

/// @brief Whether every element of `matrix` is finite.
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
bool isFinite(const glm::mat<C, R, T, Q>& matrix) {
    for (glm::length_t column = 0; column < C; ++column) {
        if (!isFinite(matrix[column])) {
            return false;
        }
    }
    return true;
}

/// @brief Whether the axis and angle of `rotation` are finite.
inline bool isFinite(const sg::Rotation& rotation) {
    return isFinite(rotation.axis()) && std::isfinite(rotation.angle());
}

/// @brief Throws DataError("Transform 'T': translation must be finite, got nan 0 0") unless the
/// value of `field` of `node` is finite.
template <class Field> void requireFinite(const sg::FieldContainer& node, const Field& field) {
    if (!isFinite(field.value())) {
        throw DataError(nodeContext(node) + ": " + field.name() + " must be finite, got " +
                        field.valueText());
    }
}

} // namespace texsplat::nodes::detail
