#pragma once

// Shared by the octree tests: deterministic random grids and a brute-force visibility check.

#include "octree/ClassifiedGrid.h"
#include "octree/View.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace texsplat::octree::test {

/// A value in [0, 1) from a fixed-seed engine, independent of the standard library's
/// distributions so the grids are the same everywhere.
inline float unitRandom(std::mt19937& engine) {
    return static_cast<float>(engine() >> 8) * (1.0f / 16777216.0f);
}

/// A grid of @p dims with random colour and extinction; about @p emptyFraction of the voxels are
/// empty, and with @p emptyCorner the low corner block (up to 4^3 voxels) is empty too, so that
/// pruning has whole subtrees to remove.
inline std::shared_ptr<ClassifiedGrid> randomGrid(glm::u64vec3 dims, unsigned seed,
                                                  float emptyFraction = 0.3f,
                                                  bool emptyCorner = true,
                                                  glm::dvec3 spacing = glm::dvec3(1.0),
                                                  glm::dvec3 origin = glm::dvec3(0.0)) {
    auto grid = std::make_shared<ClassifiedGrid>(dims, spacing, origin);
    std::mt19937 engine(seed);
    for (std::uint64_t k = 0; k < dims.z; ++k) {
        for (std::uint64_t j = 0; j < dims.y; ++j) {
            for (std::uint64_t i = 0; i < dims.x; ++i) {
                const bool corner = emptyCorner && i < 4 && j < 4 && k < 4;
                if (corner || unitRandom(engine) < emptyFraction) {
                    continue;
                }
                const glm::vec3 color(unitRandom(engine), unitRandom(engine),
                                      unitRandom(engine));
                grid->setVoxel({i, j, k}, color, 0.1f + unitRandom(engine));
            }
        }
    }
    return grid;
}

/// The world-space box of a splat's cell(s).
struct Cell {
    glm::dvec3 low;
    glm::dvec3 high;
};

/// Result of `checkVisibilityOrder()`.
struct VisibilityCheck {
    std::uint64_t orderedPairs = 0; ///< consecutive cells on a ray that were compared
    std::uint64_t violations = 0;   ///< of those, the nearer one emitted first
};

/// The interval of the ray `origin + t * direction` inside @p cell, when it has positive length.
inline bool clipRay(const Cell& cell, glm::dvec3 origin, glm::dvec3 direction, double& enter,
                    double& exit) {
    enter = -std::numeric_limits<double>::infinity();
    exit = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0.0) {
            if (origin[axis] <= cell.low[axis] || origin[axis] >= cell.high[axis]) {
                return false;
            }
            continue;
        }
        double near = (cell.low[axis] - origin[axis]) / direction[axis];
        double far = (cell.high[axis] - origin[axis]) / direction[axis];
        if (near > far) {
            std::swap(near, far);
        }
        enter = std::max(enter, near);
        exit = std::min(exit, far);
    }
    return exit - enter > 1e-9;
}

/// Brute force: shoots @p rayCount rays through random points of [@p low, @p high] (parallel to
/// the direction for an orthographic view, from the eye for a perspective one), sorts the cells
/// each ray crosses by distance along it, and counts how often a nearer cell was emitted before a
/// farther one. @p cells are in emission order.
inline VisibilityCheck checkVisibilityOrder(const std::vector<Cell>& cells, const View& view,
                                            glm::dvec3 low, glm::dvec3 high, int rayCount,
                                            unsigned seed) {
    std::mt19937 engine(seed);
    VisibilityCheck check;
    std::vector<std::pair<double, std::size_t>> hits;
    for (int ray = 0; ray < rayCount; ++ray) {
        const glm::dvec3 target =
            low + (high - low) * glm::dvec3(unitRandom(engine), unitRandom(engine),
                                            unitRandom(engine));
        const glm::dvec3 origin = view.isPerspective() ? view.eye() : target;
        const glm::dvec3 direction =
            view.isPerspective() ? glm::normalize(target - view.eye()) : view.direction();
        hits.clear();
        for (std::size_t rank = 0; rank < cells.size(); ++rank) {
            double enter = 0.0;
            double exit = 0.0;
            if (clipRay(cells[rank], origin, direction, enter, exit) &&
                (!view.isPerspective() || exit > 1e-9)) {
                hits.emplace_back(enter, rank);
            }
        }
        std::sort(hits.begin(), hits.end());
        for (std::size_t i = 1; i < hits.size(); ++i) {
            ++check.orderedPairs;
            // hits[i] is farther along the ray: it must have been emitted earlier.
            if (hits[i].second > hits[i - 1].second) {
                ++check.violations;
            }
        }
    }
    return check;
}

} // namespace texsplat::octree::test
