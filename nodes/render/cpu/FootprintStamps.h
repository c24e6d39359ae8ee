#pragma once

#include "nodes/render/cpu/detail/CacheLineAllocator.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace texsplat::render::cpu {

struct FootprintSampler;

/// @brief The footprint of an orthographic batch's unit-size splats as pixel stamps, one per
/// sub-pixel phase of the splat's centre.
///
/// Through an orthographic camera every splat of one size covers the same pixels alike, up to
/// where its centre falls within a pixel: the footprint times the length scale is tabulated
/// once per frame at every pixel of the box for kPhases × kPhases centre positions in a pixel
/// (and the next pixel's first, so that neighbours always exist), and a splat's footprint is the
/// bilinear blend of the four stamps around its centre's phase. That replaces the per-pixel map
/// to the square, the square root and the register lookup of the cubic pieces by four loads and
/// three multiply-adds. `error` is the blend's largest difference from the footprint it stands
/// for, measured when made.
///
/// Made only for a radial footprint with cubic pieces whose disc lies inside the square (the
/// paper's kernel): there the footprint falls smoothly to 0 at its reach, and the blend follows
/// it; where the square cuts the disc, or the footprint falls like a square root at its edge
/// (the truncated Gaussian), the blend would smear an edge, and those splats keep the exact
/// lookup.
struct FootprintStamps {
    /// @brief Centre positions per pixel and axis (the stamps are 1/16 pixel apart).
    static constexpr int kPhases = 16;
    /// @brief The blend's error allowed, relative to the footprint's peak: larger and the
    /// stamps are not used (a footprint narrower than a few pixels bends too much between
    /// phases).
    static constexpr double kTolerance = 1e-3;

    int columns = 0;       ///< pixels of a stamp's row
    int rows = 0;          ///< rows of a stamp
    /// @brief Floats from one stamp row to the next: kPad zeros, the row's columns, zeros to a
    /// whole cache line and at least kPad more, so that a vector of up to kPad lanes starting at
    /// any column of the row within kPad before it reads inside the row.
    int stride = 0;
    static constexpr int kPad = 8;
    int columnOffset = 0;  ///< the stamp's first column relative to the pixel holding the centre
    int rowOffset = 0;     ///< the stamp's first row relative to the pixel holding the centre
    std::size_t stampSize = 0; ///< floats per stamp: rows × stride
    /// @brief (kPhases + 1)² stamps, phase y major: stamp (qx, qy) is the footprint (times the
    /// length scale) of a splat whose centre lies qx/kPhases, qy/kPhases of a pixel past the
    /// pixel's centre.
    std::vector<float, detail::CacheLineAllocator<float>> values;
    /// @brief The pixels a blend of the stamps of one phase cell can reach: stamp columns and
    /// rows [begin, end) of the four stamps' values that are not 0.
    struct Extent {
        std::int32_t columnBegin = 0, columnEnd = 0, rowBegin = 0, rowEnd = 0;
    };
    /// @brief Per phase cell (qx, qy < kPhases, qy major) the Extent of its blends.
    std::vector<Extent> extents;
    float error = 0.0f; ///< the blend's largest |difference| from the footprint, times the scale
    float peak = 0.0f;  ///< the footprint's peak times the scale

    /// @brief The widest and tallest stamp made, in pixels: wider splats gain nothing from
    /// stamps (the exact lookup's 16-lane vectors are as cheap per pixel there), and the
    /// table grows with the square of the width (289 stamps of 32² floats: 1.2 MiB; a zoomed
    /// view's splats may be thousands of pixels wide).
    static constexpr int kLargestSide = 32;

    /// @brief Whether a batch with `sampler`, whose unit-size footprint reaches `halfExtent`
    /// pixels from its centre, may be stamped (see above).
    static bool suits(const FootprintSampler& sampler, const float (&halfExtent)[2]);

    /// @brief The stamps of unit-size splats whose pixel offset (x, y) from the centre maps to
    /// the square's (a, b) = squareFromPixel · (x, y), whose footprint reaches at most
    /// halfExtent pixels from the centre, and whose line integrals are `lengthScale` times the
    /// footprint.
    FootprintStamps(const FootprintSampler& sampler, const float (&squareFromPixel)[2][2],
                    const float (&halfExtent)[2], float lengthScale);

    /// @brief The index of stamp (qx, qy).
    static std::int32_t phaseIndex(int qx, int qy) { return qy * (kPhases + 1) + qx; }

    /// @brief Stamp `phase`'s value at (column, row) of the stamp.
    float at(std::int32_t phase, int column, int row) const {
        return values[static_cast<std::size_t>(phase) * stampSize +
                      static_cast<std::size_t>(row) * static_cast<std::size_t>(stride) +
                      static_cast<std::size_t>(kPad + column)];
    }

    /// @brief The blend at (column, row) of a splat whose centre lies in phase `phase` plus
    /// fractions (fx, fy) of a phase, as the SIMD loop computes it.
    float blend(std::int32_t phase, float fx, float fy, int column, int row) const;
};

} // namespace texsplat::render::cpu
