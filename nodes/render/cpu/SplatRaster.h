#pragma once

#include "nodes/render/SplatFootprint.h"
#include "nodes/render/SplatView.h"
#include "nodes/render/cpu/FootprintStamps.h"

#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::octree {
struct Splat;
} // namespace texsplat::octree

namespace texsplat::render::cpu {

/// @brief A splat's footprint laid out for the rasterizer, looked up at a point (a, b) of the
/// splat's square [−1, 1]²:
/// - radial (a TexturedSquare of a radial kernel): f(E·√ρ) tabulated over ρ = a² + b² ∈ [0, 2]
///   at kProfileSamples + 1 points (and a guard), linear between: two reads a pixel instead of
///   the texture's four, and closer to the kernel than the N×N texture (|error| < 1e-5 of the
///   peak for the paper's kernel at 4096 samples, against the 64² texture's 1e-3);
/// - otherwise (the polygonal Gaussian's fan): the N×N texture with a border of one texel copied
///   from the edge, bilinear, reading exactly what GL's CLAMP_TO_EDGE lookup reads.
struct FootprintSampler {
    static constexpr int kProfileSamples = 4096; ///< intervals of the radial profile over [0, 2]

    bool isRadial = false;     ///< which lookup
    int resolution = 0;        ///< texture: N, texels per side
    int stride = 0;            ///< texture: N + 2, floats per padded row
    std::vector<float> values; ///< profile (kProfileSamples + 2) or padded texels ((N + 2)²)
    float peak = 0.0f;         ///< the largest value
    /// @brief Radial: the ρ = a² + b² beyond which the profile is 0 (the kernel's support);
    /// pixels farther out add nothing and are skipped.
    float reach = 2.0f;

    /// @brief Radial: the footprint as kPieces cubics in r = √ρ over [0, √reach], each through
    /// the kernel at four points of its interval, which the SIMD loop looks up in registers
    /// instead of gathering two profile samples from memory. In p = r·piecesPerRadius ∈ [0,
    /// kPieces − 1], piece i covers p ∈ [i − ½, i + ½] (the end pieces the half inside) and
    /// pieces[k][i] is its coefficient of v^k, v = p − i: the loop finds i by rounding p.
    /// Used when `hasPieces`: their largest difference from the kernel, `pieceError`, is within
    /// kPieceTolerance of the peak, as close as the profile is (the paper's kernel: 3e-6; a
    /// truncated Gaussian, whose footprint falls to 0 like a square root at its edge, keeps the
    /// profile).
    static constexpr int kPieces = 16;
    static constexpr double kPieceTolerance = 1e-5;
    bool hasPieces = false;
    float piecesPerRadius = 0.0f; ///< (kPieces − 1) / √reach
    float pieceError = 0.0f;      ///< the largest |cubic − kernel|, measured when made
    std::array<std::array<float, kPieces>, 4> pieces{};

    /// @brief Piece `index` at `v` ∈ [−½, ½], by Horner's rule in float as the SIMD loop
    /// evaluates it (with fused multiply-adds).
    float piece(int index, float v) const {
        const auto i = static_cast<std::size_t>(index);
        return std::fma(std::fma(std::fma(pieces[3][i], v, pieces[2][i]), v, pieces[1][i]), v,
                        pieces[0][i]);
    }

    /// @brief The sampler of `footprint`: radial when it is a square (TexturedSquare,
    /// CombinedMarks) with its kernel.
    explicit FootprintSampler(const SplatFootprint& footprint);
};

/// @brief One splat set up for rasterizing: the projective map from a pixel to the splat's
/// square, its depth plane, its medium and the pixels it may cover.
///
/// The splat's square is laid out exactly as the GL backend's vertex shader lays it (see
/// detail/SplatShaders.h): centre c, in the plane perpendicular to e = S⁻¹d in voxel space,
/// axes u, v, `extent · size` voxels from the centre. A point (a, b) ∈ [−1, 1]² of it is in clip
/// space C0 + a·Cu + b·Cv, so pixel centre (x + ½, y + ½, 1) maps back to (a, b) by the inverse of
/// a 3×3 matrix: `square` gives (a′, b′, w′) with (a, b) = (a′, b′)/w′ and w′ = 1/W_clip (> 0 in
/// front of the eye). For an orthographic camera w′ = 1 and the map is affine. The window depth
/// z_ndc of the square is affine in the pixel (a plane's z/w is), `depth` holds it.
struct SplatRaster {
    float square[9];   ///< pixel centre (x, y, 1) → (a′, b′, w′), row major
    float depth[3];    ///< pixel centre (x, y, 1) → z_ndc of the square
    float color[3];    ///< emission C per unit length
    float extinction;  ///< τ per unit length
    float lengthScale; ///< footprint texel → line integral: size / |S⁻¹d|
    std::int32_t columnBegin, columnEnd; ///< pixels [begin, end) the square may cover
    std::int32_t rowBegin, rowEnd;       ///< rows [begin, end), top row first
    std::int32_t flags;                  ///< kProjective | kClipped | kStamped
    // Stamped splats only (kStamped, see FootprintStamps): the pixel of the stamp's first column
    // and row, and the stamp of the centre's nearest phase.
    std::int32_t stampColumn, stampRow;
    std::int32_t stampPhase;

    static constexpr std::int32_t kProjective = 1; ///< w′ varies over the pixels
    static constexpr std::int32_t kClipped = 2; ///< crosses the near or far plane: clip per pixel
    static constexpr std::int32_t kStamped = 8; ///< the footprint from FootprintStamps

    /// @brief Whether the splat covers no pixel of the image (then nothing else is set).
    bool isEmpty() const { return columnBegin >= columnEnd || rowBegin >= rowEnd; }
};

/// @brief What the SIMD set-up of splats in perspective (setUpProjective()) needs of a batch.
struct ProjectiveRows {
    float pixelFromLocal[4][4]{}; ///< local point → (x·W, y·W, W, z_clip), row major
    float pixelFromVoxel[4][3]{}; ///< voxel-space offset (before the spacing) → the same
    float eye[3]{};               ///< local space (perspective)
    float direction[3]{};         ///< unit viewing direction, local space
    float inverseSpacing[3]{};    ///< 1 / voxel spacing
    float extent = 1.6f;          ///< square half-width in voxels at size 1
    /// @brief Radius in square half-widths beyond which the footprint is 0 (a radial footprint's
    /// √reach): the pixel box bounds that disc's image where it is tighter than the square's;
    /// 0: the square's box.
    float discRadius = 0.0f;
    int width = 1;                ///< image columns
    int height = 1;               ///< image rows
    bool isPerspective = false;   ///< splats face the eye (else `direction`)
};

/// @brief Sets up `count` splats for `rows`, as SplatSetup says, SIMD over splats (Highway,
/// dispatched at run time); out[i] is splats[i]'s raster.
void setUpProjective(const ProjectiveRows& rows, const octree::Splat* splats, std::size_t count,
                     SplatRaster* out);

/// @brief Sets up the splats of one batch for rasterizing as the GL backend draws them (same
/// square, same texture coordinates).
///
/// A perspective view turns every splat to the eye, so each gets its own square and map:
/// setUpProjective() computes them for a vector of splats at a time. An orthographic view (with
/// an affine model matrix) turns them all alike: the map from pixels to the square is computed
/// once at size 1 and each splat only scales and moves it.
class SplatSetup {
public:
    /// @brief The setup for splats seen through `view`, squares `extent` voxels from the centre
    /// at size 1, in an image of `width` x `height` pixels. With `discRadius` > 0 the footprint
    /// is 0 beyond that radius (in square half-widths, ProjectiveRows::discRadius), and the
    /// pixel boxes bound the disc.
    SplatSetup(const SplatView& view, float extent, int width, int height, float discRadius = 0.0f);

    /// @brief Sets up `count` splats into `out`: an empty raster for a splat that covers no
    /// pixel or lies wholly outside the near/far planes.
    void setUp(const octree::Splat* splats, std::size_t count, SplatRaster* out) const;

    /// @brief For an orthographic view of scalar splats whose footprint `sampler` suits stamps
    /// (FootprintStamps::suits(): the paper's kernel, splats at most kLargestSide pixels
    /// wide), `stamps` is its footprint tabulated per sub-pixel phase (made for this view:
    /// stampsFor()): unit-size splats that do not cross the near or far plane are then set up
    /// as stamped. Null: none are.
    void setStamps(std::shared_ptr<const FootprintStamps> stamps) { mStamps = std::move(stamps); }

    /// @brief The stamps of `sampler` for this view, or null where they do not apply
    /// (FootprintStamps::suits()) or stray from the footprint by more than
    /// FootprintStamps::kTolerance of its peak at the most phases made.
    std::shared_ptr<const FootprintStamps> stampsFor(const FootprintSampler& sampler) const;

    /// @brief Whether the view maps every splat alike (orthographic, affine): then
    /// stampGeometry() says how.
    bool isAffine() const { return mIsAffine; }

    /// @brief How a unit-size splat lies in pixels (isAffine() only).
    const StampGeometry& stampGeometry() const { return mUnit; }

    /// @brief The stamps of setStamps(), or null.
    const FootprintStamps* stamps() const { return mStamps.get(); }

    /// @brief One splat of an affine view (isAffine()) set up, as setUp() sets it up: an empty
    /// raster where it covers no pixel or lies wholly outside the near/far planes.
    SplatRaster orthographic(const octree::Splat& splat) const;

    /// @brief Where a splat's centre lies: pixel coordinates x, y (pixel c's centre at c + ½)
    /// and window depth z_ndc.
    struct Centre {
        double x, y, z;
    };

    /// @brief The Centre of a splat at `position` (local space) in an affine view (isAffine()),
    /// each coordinate the sum ((c + r_z·p_z) + r_y·p_y) + r_x·p_x over its row of
    /// pixelFromLocal, in double and in this order. Its products are exact (floats), so only the
    /// order of the sums decides the bits: a voxel's splat placed without a list (VoxelRaster,
    /// which sums a row of voxels' common terms once) lands exactly where the list's splat of it
    /// does, on the same stamp.
    Centre centreOf(const glm::vec3& position) const {
        const auto sum = [&](const float(&row)[4]) {
            return (double(row[3]) + double(row[2]) * double(position.z) +
                    double(row[1]) * double(position.y)) +
                   double(row[0]) * double(position.x);
        };
        return {sum(mRows.pixelFromLocal[0]), sum(mRows.pixelFromLocal[1]),
                sum(mRows.pixelFromLocal[3])};
    }

    /// @brief How far z_ndc reaches from a unit-size splat's centre over its square (isAffine()):
    /// orthographic() leaves a splat out that lies wholly outside [−1, 1] by it, and does not
    /// stamp one that crosses ±1.
    float depthReach() const { return mDepthReach; }

    /// @brief How z_ndc changes per pixel along x and y over a splat's square (isAffine()).
    float depthGradient(int axis) const { return mDepthGradient[axis]; }

    /// @brief What the set-up knows of the view.
    const ProjectiveRows& rows() const { return mRows; }

private:
    // Sets `raster` (of a unit-size splat centred at `centre`) up as stamped; false (nothing
    // changed) where the centre is too far out for an int.
    bool stamp(SplatRaster& raster, const Centre& centre) const;

    SplatView mView;
    ProjectiveRows mRows;
    // Orthographic views: the square at size 1 (its map from pixels, its box and length scale)
    // and its depth.
    bool mIsAffine = false;
    StampGeometry mUnit;
    float mDepthGradient[2]{};      // z_ndc per pixel, x and y
    float mDepthReach = 0.0f;       // |z_ndc| the square reaches from its centre
    std::shared_ptr<const FootprintStamps> mStamps;
};

} // namespace texsplat::render::cpu
