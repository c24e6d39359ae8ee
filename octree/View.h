#pragma once

#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/geometric.hpp>

#include <array>

namespace texsplat::octree {

/// @brief What the octree needs to know of a camera to order and cull splats: the projection,
/// the viewing direction and, for a perspective camera, the eye position (world space).
class View {
public:
    /// @brief The two projections of Inventor's cameras.
    enum class Projection { Orthographic, Perspective };

    /// @brief A parallel projection looking along @p direction.
    /// @throws DataError when the direction is zero or not finite.
    [[nodiscard]] static View orthographic(glm::dvec3 direction);

    /// @brief A perspective projection from @p eye, looking along @p direction.
    /// @throws DataError when the eye is not finite or the direction is zero or not finite.
    [[nodiscard]] static View perspective(glm::dvec3 eye, glm::dvec3 direction);

    /// @brief The four sides of a camera's view volume (left, right, bottom, top), each a plane
    /// (a, b, c, d) with a·x + b·y + c·z + d >= 0 on the inner side, in world space.
    using Sides = std::array<glm::dvec4, 4>;

    /// @brief This view seeing only what lies within @p sides, where a splat reaches at most
    /// @p reach times its node's largest edge from the node's centre (the centre of its cells):
    /// a node whose splat lies wholly outside (isOutOfSight()) draws nothing, so a cut need not
    /// draw it, nor refine a node whose whole subtree does (isSubtreeOutOfSight(); Refiner).
    /// Ordering is unchanged. A plane that is not finite hides
    /// nothing.
    /// @throws DataError when @p reach is negative or not finite.
    [[nodiscard]] View seeingOnly(const Sides& sides, double reach) const;

    /// @brief Whether the splat of a node with cells [@p low, @p high] lies wholly outside one of
    /// the sides of seeingOnly() (never for a view without them): the node's own splat, which
    /// reaches beyond its cells by reach · its largest edge less its smallest half-width (at most
    /// half the reach). Not inherited: a thin child clipped at the grid's far faces can splat as
    /// large as its parent and reach past it (isSubtreeOutOfSight() is).
    [[nodiscard]] bool isOutOfSight(glm::dvec3 low, glm::dvec3 high) const;

    /// @brief Whether the splats of a node with cells [@p low, @p high] and of every node within
    /// it lie wholly outside one of the sides: its cells widened by reach · its largest edge,
    /// which no node within it (cells inside, edge no larger) reaches past. So when a node's
    /// subtree is out of sight, so is each of its children's.
    [[nodiscard]] bool isSubtreeOutOfSight(glm::dvec3 low, glm::dvec3 high) const;

    /// @brief Whether the splats of nodes of largest edge @p nodeEdge and smallest half-width
    /// @p nodeHalfWidth within the cells [@p low, @p high] (say the voxels of a block) all lie
    /// wholly outside one of the sides: each reaches reach · nodeEdge from its centre, so beyond
    /// its cells by that less its half-width (credited up to half the reach).
    [[nodiscard]] bool isOutOfSight(glm::dvec3 low, glm::dvec3 high, double nodeEdge,
                                    double nodeHalfWidth) const;

    /// @brief Whether the box [@p low, @p high] lies wholly inside every side of seeingOnly()
    /// (always for a view without them): then no splat of a node within it is out of sight, and
    /// a traversal need not ask isOutOfSight() below it.
    [[nodiscard]] bool isWhollyInSight(glm::dvec3 low, glm::dvec3 high) const;

    /// @brief Whether the view has sides (seeingOnly()).
    [[nodiscard]] bool hasSides() const { return mHasSides; }

    /// @brief The projection.
    [[nodiscard]] Projection projection() const { return mProjection; }

    /// @brief Whether the projection is perspective.
    [[nodiscard]] bool isPerspective() const { return mProjection == Projection::Perspective; }

    /// @brief Unit viewing direction (from the eye into the scene).
    [[nodiscard]] glm::dvec3 direction() const { return mDirection; }

    /// @brief Eye position; meaningful for a perspective view only.
    [[nodiscard]] glm::dvec3 eye() const { return mEye; }

    /// @brief Whether, along world axis @p axis, the far side of the plane `axis = planePosition`
    /// is the upper side (larger coordinates). For an orthographic view this depends only on the
    /// direction; for a perspective view on which side of the plane the eye is. A view parallel
    /// to the plane, or an eye on it, sees neither side behind the other: the answer is "upper".
    [[nodiscard]] bool isUpperSideFar(int axis, double planePosition) const {
        return isPerspective() ? mEye[axis] <= planePosition : mDirection[axis] >= 0.0;
    }

    /// @brief Signed distance of @p point in front of the eye plane along the view direction
    /// (perspective) or its depth along the direction (orthographic, from the world origin).
    [[nodiscard]] double depth(glm::dvec3 point) const {
        return glm::dot(point - mEye, mDirection);
    }

    /// @brief Whether the axis-aligned box [@p low, @p high] lies wholly behind the eye plane of
    /// a perspective view (never for an orthographic view): nothing in it can be projected.
    [[nodiscard]] bool isBoxBehindEye(glm::dvec3 low, glm::dvec3 high) const;

    /// @brief Whether a perspective view sees the whole box [low, high] in front of the eye,
    /// with a margin for rounding (so that no point of it has depth() <= 0); always true for an
    /// orthographic view.
    [[nodiscard]] bool isBoxInFrontOfEye(glm::dvec3 low, glm::dvec3 high) const;

private:
    // The corner of the box [low, high] farthest along the direction.
    glm::dvec3 farthestCorner(glm::dvec3 low, glm::dvec3 high) const;

    View(Projection projection, glm::dvec3 direction, glm::dvec3 eye);

    Projection mProjection;
    glm::dvec3 mDirection;
    glm::dvec3 mEye;
    bool mHasSides = false;
    Sides mSides{};
    double mReach = 0.0;
};

} // namespace texsplat::octree
