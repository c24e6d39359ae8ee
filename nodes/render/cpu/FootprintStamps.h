#pragma once

#include "nodes/render/cpu/detail/CacheLineAllocator.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace texsplat::render::cpu {

struct FootprintSampler;

/// @brief How an orthographic view lays out a unit-size splat in pixels: what FootprintStamps
/// are made for (and kept while it stays the same).
struct StampGeometry {
    float squareFromPixel[2][2]{}; ///< pixel offset (x, y) from the centre → the square's (a, b)
    float halfExtent[2]{};         ///< pixels the footprint reaches from the centre, x and y
    float lengthScale = 1.0f;      ///< footprint → line integral

    /// @brief Whether every member is equal (floats compared exactly).
    bool operator==(const StampGeometry& other) const;
    bool operator!=(const StampGeometry& other) const { return !(*this == other); }
};

/// @brief The footprint of an orthographic batch's unit-size splats as pixel stamps, one per
/// sub-pixel phase of the splat's centre: a splat takes the stamp of the phase nearest its
/// centre and nothing else per pixel.
///
/// Through an orthographic camera every splat of one size covers the same pixels alike, up to
/// where its centre falls within a pixel: the footprint times the length scale is tabulated
/// once per batch at every pixel of the box for `phases()` × `phases()` centre positions in a
/// pixel. A splat whose centre lies within half a phase of a stamp's draws that stamp, its
/// footprint moved by at most 1/(2·phases()) of a pixel along each axis: one load per vector of
/// pixels instead of the per-pixel map to the square, the square root and the cubic pieces.
/// `error` is the largest difference between a stamp and the footprint of any centre it stands
/// for, measured when made; the phases are doubled from kPhases until it is within kTolerance
/// of the peak (narrow footprints bend more within a phase) or the table would outgrow
/// kLargestTable.
///
/// A stamp is `rows` rows of `columns` floats, a whole number of kLanes, rows one after the
/// other: one SIMD vector of 8 lanes holds a row, one of 16 (AVX-512) two rows of an 8-column
/// stamp. A splat's row is composited at any column (unaligned), so each of its vectors is one
/// load and one store per plane.
///
/// Made only for a radial footprint with cubic pieces whose disc lies inside the square (the
/// paper's kernel): there the footprint falls smoothly to 0 at its reach; where the square cuts
/// the disc, or the footprint falls like a square root at its edge (the truncated Gaussian), a
/// stamp would smear an edge, and those splats keep the exact lookup.
struct FootprintStamps {
    /// @brief The fewest centre positions per pixel and axis (a power of two).
    static constexpr int kPhases = 16;
    /// @brief The error allowed relative to the footprint's peak before the phases are doubled.
    static constexpr double kTolerance = 0.025;
    /// @brief The largest table made when doubling the phases (floats).
    static constexpr std::size_t kLargestTable = std::size_t{1} << 18;
    /// @brief Stamp rows are whole multiples of this many floats.
    static constexpr int kLanes = 8;
    /// @brief The widest and tallest stamp made, in pixels: wider splats gain nothing from
    /// stamps (the exact lookup's 16-lane vectors are as cheap per pixel there), and the table
    /// grows with the square of the width (a zoomed view's splats may be thousands of pixels
    /// wide). ColorPlanes::kPadding holds a row this wide starting left of the image.
    static constexpr int kLargestSide = 32;

    int phaseBits = 4;     ///< log2 of phases()
    int columns = 0;       ///< floats of a stamp's row (a multiple of kLanes)
    int rows = 0;          ///< rows of a stamp
    int columnOffset = 0;  ///< the stamp's first column relative to the pixel holding the centre
    int rowOffset = 0;     ///< the stamp's first row relative to the pixel holding the centre
    std::size_t stampSize = 0; ///< floats per stamp: rows × columns
    /// @brief phases()² stamps, phase y major: stamp (qx, qy) is the footprint (times the length
    /// scale) of a splat whose centre lies qx/phases(), qy/phases() of a pixel past the centre of
    /// the pixel holding it.
    std::vector<float, detail::CacheLineAllocator<float>> values;
    /// @brief The pixels a stamp reaches: its rows and columns [begin, end) holding a value that
    /// is not 0.
    struct Extent {
        std::int32_t columnBegin = 0, columnEnd = 0, rowBegin = 0, rowEnd = 0;
    };
    /// @brief Per stamp (phaseIndex()), its Extent.
    std::vector<Extent> extents;
    float error =
        0.0f; ///< the largest |stamp − footprint| of a centre it stands for, times the scale
    float peak = 0.0f;  ///< the footprint's peak times the scale

    /// @brief Centre positions per pixel and axis.
    int phases() const { return 1 << phaseBits; }

    /// @brief Whether a batch with `sampler` seen with `geometry` may be stamped (see above).
    static bool suits(const FootprintSampler& sampler, const StampGeometry& geometry);

    /// @brief The stamps of `sampler`'s unit-size splats laid out by `geometry`.
    FootprintStamps(const FootprintSampler& sampler, const StampGeometry& geometry);

    /// @brief The index of stamp (qx, qy).
    std::int32_t phaseIndex(int qx, int qy) const { return (qy << phaseBits) + qx; }

    /// @brief Stamp `phase`'s value at (column, row) of the stamp.
    float at(std::int32_t phase, int column, int row) const {
        return values[static_cast<std::size_t>(phase) * stampSize +
                      static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                      static_cast<std::size_t>(column)];
    }

    /// @brief Where a splat centred at pixel coordinates (x, y) (pixel c's centre at c + ½) is
    /// stamped: the pixel of its stamp's first column and row, and the stamp.
    struct Place {
        std::int32_t column, row, phase;
    };

    /// @brief The Place of a splat centred at (`centreX`, `centreY`): the nearest phase, ⌊(x −
    /// ½)·phases + ½⌋ (the product is exact, so every caller places a centre alike); false where
    /// the centre is too far out for an int (|coordinate| ≥ 2^26 pixels), with `place`
    /// unchanged.
    bool place(double centreX, double centreY, Place& place) const {
        return placeInPhases(std::floor((centreX - 0.5) * phases() + 0.5),
                             std::floor((centreY - 0.5) * phases() + 0.5), place);
    }

    /// @brief The bound on a centre in phases (|x| and |y|) below which placeInPhases() places it.
    static constexpr double kPhaseLimit = 1 << 30;

    /// @brief place() of a centre already in phases: the nearest phase's whole numbers (x, y)
    /// = ⌊(centre − ½)·phases + ½⌋.
    bool placeInPhases(double nearestX, double nearestY, Place& place) const {
        if (!(std::abs(nearestX) < kPhaseLimit && std::abs(nearestY) < kPhaseLimit)) {
            return false;
        }
        const auto wholeX = static_cast<std::int32_t>(nearestX);
        const auto wholeY = static_cast<std::int32_t>(nearestY);
        const std::int32_t mask = phases() - 1;
        // An arithmetic shift is a floor division by phases() (C++20 defines it; GCC, Clang
        // and MSVC always have): the pixel holding the centre.
        place.column = (wholeX >> phaseBits) + columnOffset;
        place.row = (wholeY >> phaseBits) + rowOffset;
        place.phase = phaseIndex(wholeX & mask, wholeY & mask);
        return true;
    }
};

} // namespace texsplat::render::cpu
