#pragma once

#include "nodes/render/MarkDrawing.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace texsplat::render {

struct FrameSplats;

/// @brief One mark of a frame as every backend draws it: an oriented streak in the image, in
/// pixels (x to the right, y down, pixel (i, j) covering [i, i + 1) × [j, j + 1)).
///
/// At a point (x, y) of the image, with u and v its offsets from the centre along and across
/// the axis, the mark covers s = u / halfLength ∈ [−1, 1] (tail to head) by t = v / halfWidth
/// ∈ [−1, 1] with opacity alpha · markProfile(type, s, t, head), colour `color` (BLEND: mixed
/// towards the batch's blend colour by the same profile), composited "over" at `depth`.
struct ScreenMark {
    float centre[2];  ///< pixels
    float axis[2];    ///< unit, pointing at the head (downstream)
    float halfLength; ///< pixels along the axis, >= halfWidth
    float halfWidth;  ///< pixels across
    float head;       ///< the head's fall as a fraction of halfLength, (0, 1]
    float depth;      ///< z_ndc of the centre, for the depth test against meshes
    float alpha;      ///< peak opacity, [0, 1]; 0 draws nothing
    float color[3];   ///< the mark's colour (display values, not premultiplied)

    /// @brief Whether the mark draws nothing.
    bool isEmpty() const { return !(alpha > 0.0f); }
    /// @brief Half the height of the mark's box: the rows it may cover reach this far from the
    /// centre.
    float reachY() const { return halfLength * std::abs(axis[1]) + halfWidth * std::abs(axis[0]); }
    /// @brief Half the width of the mark's box.
    float reachX() const { return halfLength * std::abs(axis[0]) + halfWidth * std::abs(axis[1]); }
};

/// @brief A mark's opacity profile at (s, t) ∈ [−1, 1]² (0 outside), the reference that the
/// backends' SIMD loop and fragment shader evaluate alike:
/// - along the axis, a ramp r(s) rising linearly from 0 at the tail (s = −1) to 1 at
///   s = 1 − head, then falling linearly to 0 at the head (s = 1): brighter downstream, a sharp
///   front, as oriented line integral convolution draws flow (Wegenkittl et al. 1997);
/// - across it, Scratches: (1 − t²)² (smooth, 1.1 half-widths wide at half height);
///   Particles: max(0, τ − t²)² with τ rising linearly from MarkDrawing::kParticleTail at the
///   tail to 1 at the head, so the comet narrows and dims towards its tail.
inline float markProfile(MarkType type, float s, float t, float head) {
    const float ramp =
        std::clamp(std::min((s + 1.0f) / (2.0f - head), (1.0f - s) / head), 0.0f, 1.0f);
    constexpr float kTail = MarkDrawing::kParticleTail;
    const float taper =
        type == MarkType::Particles ? kTail + (1.0f - kTail) * 0.5f * (s + 1.0f) : 1.0f;
    const float across = std::max(taper - t * t, 0.0f);
    return ramp * across * across;
}

/// @brief ∫∫ markProfile(type, s, t, head) ds dt over [−1, 1]²: a mark's area in units of
/// halfLength · halfWidth (Scratches: 16/15 for any head).
float markProfileArea(MarkType type, float head);

/// @brief A mark's half-length and half-width in pixels, and its head as a fraction of the
/// half-length (ScreenMark), where a voxel is `pixels` pixels wide and the mark's projection is
/// `foreshortening` (0 to 1) of its length: `drawing`'s length and width, at least the least
/// sizes in pixels.
struct MarkSize {
    float halfLength;
    float halfWidth;
    float head;

    MarkSize(const MarkDrawing& drawing, float pixels, float foreshortening);
};

/// @brief The area in square voxels (at `pixels` pixels a voxel) that one mark of a voxel
/// covers, drawn in the image plane: halfLength · halfWidth · markProfileArea() / pixels². What
/// a node divides the image's coverage by to get its marks per voxel.
float markArea(const MarkDrawing& drawing, float pixels);

/// @brief Pixels per voxel of `batch` at `local` (a point of its local space), across the line
/// of sight, in an image of `width` x `height` pixels (the geometric mean of the two image axes
/// where a model matrix scales them differently).
float pixelsPerVoxel(const FrameSplats& batch, int width, int height, const glm::vec3& local);

/// @brief The marks of `batch` (a vector or combined splat batch) in an image of `width` x
/// `height` pixels, one per emitted mark (octree::SplatList::marks(), in that order, so that
/// the list's markBegin() offsets index both); a mark that draws nothing (behind the eye, out
/// of the depth range, a zero vector) gets alpha 0. Fills `marks` in parallel (oneTBB), the same
/// values for any number of threads.
///
/// How each mark is placed (docs/vector-splats.md, "How marks are drawn"): at animation phase
/// p its life cycle is at u = frac(phase_mark + p); its centre has moved (u − ½) mark lengths
/// along its unit vector from where it was emitted, and it fades in and out over the first and
/// last MarkDrawing::kLifeFade of the cycle; the part of it outside the grid's box
/// (MarkDrawing::dataLow, dataHigh) is cut off. Its ends, half a mark length either side along the
/// vector, project to the image (so a vector towards the eye gives a short mark); a mark is
/// never narrower than MarkDrawing::kMinHalfWidthPixels nor, in the image plane, shorter than
/// kMinHalfLengthPixels, and never shorter than wide. Its colour is its voxel's (combined
/// splats: the blend colour, or black with MODULATE).
///
/// Its opacity carries the medium it stands for: its voxel's optical depth τ·ℓ through the
/// voxel's cell (ℓ the cell's depth along the line of sight), over the cell's area on screen k²
/// (k: pixels per voxel there), is shared among the voxel's expected d marks
/// (MarkDrawing::marksPerVoxel) of area a each, so a mark's peak optical depth is
/// τ·ℓ·k² / (d·a) and alpha = 1 − e^(−that · fade) (over the mean fade). Where the medium is
/// dense the marks are opaque; where it is thin, faint; and the image is about as opaque as the
/// volume's, whatever the density of marks.
void makeScreenMarks(const FrameSplats& batch, int width, int height,
                     std::vector<ScreenMark>& marks);

} // namespace texsplat::render
