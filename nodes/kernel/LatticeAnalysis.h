#pragma once

#include "nodes/kernel/RadialKernel.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace texsplat::kernel {

/// @brief Voxel spacing (sx, sy, sz) of the lattice the kernel reconstructs on, in the kernel's
/// length unit; (1, 1, 1) is the paper's cubic lattice.
using LatticeSpacing = std::array<double, 3>;

/// @brief "(sx, sy, sz)", the form a spacing takes in messages.
std::string spacingText(const LatticeSpacing& spacing);

/// @brief How flat the 3D reconstruction c(x,y,z) = Σ h(x−i sx, y−j sy, z−k sz) of a constant
/// field is (Crawfis & Max 1993, equation 2): deviations are relative to the mean of c.
struct Lattice3dStatistics {
    double mean = 0.0;          ///< mean of c over the unit cell (= ∫h / cell volume, exactly)
    double relativeRms = 0.0;   ///< r.m.s. of c − mean over the cell, divided by the mean
    double minDeviation = 0.0;  ///< min of c/mean − 1
    std::array<double, 3> minAt{}; ///< where (folded into [0, sx/2]×[0, sy/2]×[0, sz/2])
    double maxDeviation = 0.0;  ///< max of c/mean − 1
    std::array<double, 3> maxAt{}; ///< where (folded likewise)
};

/// @brief The sum of footprints of one layer of splats projected along z (the paper's figure 2):
/// absolute values, so a kernel normalized to ∫h = 1 on the unit lattice has mean 1.
struct Layer2dStatistics {
    double mean = 0.0; ///< mean of the sum over the cell (= ∫h / (sx sy), exactly)
    double max = 0.0;
    std::array<double, 2> maxAt{}; ///< folded into [0, sx/2]×[0, sy/2]
    double min = 0.0;
    std::array<double, 2> minAt{};
};

/// @brief The lattice measures of a radial kernel on a (possibly anisotropic) voxel lattice.
///
/// The r.m.s. deviation is exact up to rounding, not sampled: the mean of c² over a cell equals
/// Σₘ A(|m|) / V, the kernel's autocorrelation A summed over lattice vectors m, and A(d) reduces
/// to a 1D integral of g(r) r times a shell antiderivative, which Gauss–Legendre integrates
/// exactly on each polynomial piece. So the optimizer's objective has no sampling noise and no
/// false minima from a moving quadrature grid (docs/kernel.md). The extremes are found by a grid
/// search refined with Nelder–Mead. The kernel must outlive the analysis.
///
/// The run time of relativeRms() grows with the number of distinct lengths of lattice vectors
/// shorter than 2t, about (π/6)(2t)³ / (sx sy sz) on a lattice without symmetries, so the support
/// is bounded in cube roots of the cell volume (docs/kernel.md section 7 has the measurements).
class LatticeAnalysis {
public:
    /// @brief The largest support is this many cube roots of the cell volume: 4 voxels on the
    /// unit lattice, at most ~270 distinct distances, so that one optimization (a few thousand
    /// analyses) takes at most about 2 s on any lattice (1.6 s at t = 4 on (1, 1.01, 1.02), where
    /// t = 6.5 took 2.9 s at 5.3 ms an analysis).
    static constexpr double kMaxSupportInCellSizes = 4.0;

    /// @brief The largest spacing may be at most this many times the smallest. A kernel must
    /// reach across the largest spacing, so the distances to sum grow with the ratio; 4 is the
    /// most for which the support `texsplat kernel` defaults to on a non-cubic lattice, 1.556228
    /// times the largest spacing, stays within maxSupport (on (1, 1, r) up to r = 4.12).
    static constexpr double kMaxSpacingRatio = 4.0;

    /// @brief Throws DataError unless every spacing is finite and positive and the largest is at
    /// most kMaxSpacingRatio times the smallest.
    static void checkSpacing(const LatticeSpacing& spacing);

    /// @brief The largest support analysed on this lattice: kMaxSupportInCellSizes times
    /// ∛(sx sy sz).
    static double maxSupport(const LatticeSpacing& spacing);

    /// @brief Analyses kernel on the lattice with the given spacing. Throws DataError for a bad
    /// spacing (checkSpacing) or a kernel support above maxSupport(spacing).
    explicit LatticeAnalysis(const RadialKernel& kernel, const LatticeSpacing& spacing = {1, 1, 1});

    /// @brief Refused: the analysis keeps a reference, which a temporary kernel would leave
    /// dangling.
    explicit LatticeAnalysis(const RadialKernel&& kernel,
                             const LatticeSpacing& spacing = {1, 1, 1}) = delete;

    /// @brief ∫h over R³ = 4π ∫ g(r) r² dr.
    double volumeIntegral() const;

    /// @brief The relative r.m.s. deviation of c over the cell; +∞ when ∫h ≤ 0 (no relative
    /// measure exists), which the optimizer treats as outside the domain.
    double relativeRms() const;

    /// @brief c(x, y, z): the reconstruction of the constant field 1 at a point.
    double reconstruction(const std::array<double, 3>& point) const;

    /// @brief The mean, r.m.s. and extreme relative deviations of c.
    Lattice3dStatistics lattice3d() const;

    /// @brief Σ f(|(x − i sx, y − j sy)|): one layer of footprints projected along z.
    double layerSum(const std::array<double, 2>& point) const;

    /// @brief The mean, max and min of the layer sum and where they occur.
    Layer2dStatistics layer2d() const;

private:
    const RadialKernel& mKernel;
    LatticeSpacing mSpacing;
    std::vector<std::pair<long double, int>> mDistances; ///< |m| < 2t and how many m have it
};

} // namespace texsplat::kernel
