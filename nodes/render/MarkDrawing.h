#pragma once

#include <glm/vec3.hpp>

#include <limits>

namespace texsplat::render {

/// @brief The texture operators of the paper's vector splats (Crawfis & Max 1993, after SGI
/// GL's texture environment): what colour a mark has.
enum class MarkOperator {
    Modulate, ///< marks in the splat's own colour
    Blend,    ///< marks dissolving from the splat's colour at the tail to `blendColor` at the head
};

/// @brief The shape of the marks (docs/vector-splats.md, "How marks look"). Both have a head and
/// a fading tail, so that a still image tells which way the flow goes.
enum class MarkType {
    Particles, ///< comets: a round head and a short, thinner tail
    Scratches, ///< streaks of even width whose opacity rises from the tail to a sharp head
};

/// @brief How a vector or combined splat batch draws its marks in one frame, besides the view:
/// what render::ScreenMarks needs to place each emitted mark (octree::SplatMark) in the image.
struct MarkDrawing {
    MarkType type = MarkType::Scratches;                   ///< the marks' shape
    MarkOperator textureOperator = MarkOperator::Modulate; ///< the marks' colour
    glm::vec3 blendColor{1.0f}; ///< the colour of MarkOperator::Blend (and of combined marks)
    /// @brief The animation phase in cycles: every mark moves one life cycle along its vector
    /// per unit (only the fraction matters).
    float phase = 0.0f;
    float length = 2.5f; ///< a voxel's mark length, in voxels along the vector
    float width = 0.08f; ///< a voxel's mark width, in voxels
    /// @brief The marks per voxel this frame draws (VectorMarkSplat::frameMarks): a mark's
    /// opacity is that of the medium it stands for, spread over the marks.
    double marksPerVoxel = 0.0;
    /// @brief The box of the grid's cells in the batch's local space: marks are cut to it.
    glm::vec3 dataLow{-std::numeric_limits<float>::infinity()};
    glm::vec3 dataHigh{std::numeric_limits<float>::infinity()}; ///< its upper corner
    /// @brief Combined splats: marks are drawn over the scalar splat, in `blendColor` (BLEND)
    /// or black (MODULATE), at `contrast` times their opacity.
    bool isCombined = false;
    float contrast = 1.0f; ///< combined splats: how strongly the marks show, [0, 1]

    /// @brief Half a mark's width is at least this many pixels (its width at half opacity is
    /// 1.1 times that, 2.7 pixels): thinner, it would alias when the voxels are small on screen,
    /// and read turned towards the image's diagonals (a line 1.6 pixels wide at 30° reads as 36°
    /// by central differences, one 2.7 wide as 33°).
    static constexpr float kMinHalfWidthPixels = 2.5f;
    /// @brief Half a mark's length is at least this many pixels when it lies in the image plane
    /// (a vector towards the eye shortens it): shorter, it would not show a direction (a mark
    /// four times as long as it is wide).
    static constexpr float kMinHalfLengthPixels = 10.0f;
    /// @brief The head of a mark falls from its full opacity to 0 over this many pixels (and at
    /// least over its half-width): sharp enough to show which way the flow goes, soft enough
    /// that its edge across the flow does not outweigh the mark's long sides.
    static constexpr float kHeadPixels = 3.0f;
    /// @brief Particles: the tail's τ (markProfile()), so that it is √0.4 = 0.63 times as wide as
    /// the head and a sixth as bright.
    static constexpr float kParticleTail = 0.4f;
    /// @brief The fraction of a mark's life cycle over which it fades in, and again out (a mark
    /// is born where its cycle starts and dies one mark length further on).
    static constexpr float kLifeFade = 0.15f;
};

} // namespace texsplat::render
