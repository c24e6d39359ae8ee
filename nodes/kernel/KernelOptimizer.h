#pragma once

#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/GaussianKernel.h"
#include "nodes/kernel/LatticeAnalysis.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace texsplat::kernel {

/// @brief The paper's four free parameters of the cubic kernel with a = 1 (section 2): knot s,
/// support t, and the coefficients b (of r²) and d (of (t−r)²); c and e follow from C¹ at s.
struct KernelShape {
    double knot = 0.0;
    double support = 0.0;
    double b = 0.0;
    double d = 0.0;
};

/// @brief What the optimizer searches over and how long.
struct OptimizerOptions {
    LatticeSpacing spacing{1.0, 1.0, 1.0}; ///< the lattice the kernel must reconstruct on
    std::optional<double> fixedSupport;    ///< keep t at this value (free s, b, d) when set
    int maxRestarts = 30;                  ///< Nelder–Mead restarts from the best point
    int maxEvaluations = 40000;            ///< objective evaluations over all restarts
    int progressInterval = 100;            ///< iterations between progress reports
};

/// @brief One point on the optimizer's path: the best shape after an iteration group.
struct OptimizerStep {
    int restart = 0;
    int iteration = 0;
    int evaluations = 0;
    KernelShape shape;
    double relativeRms = 0.0;
};

/// @brief The optimizer's answer: the shape, the kernel normalized as in the paper (divided by
/// the mean of the reconstruction, so that mean is 1), its r.m.s. and the path that led there.
struct OptimizerResult {
    KernelShape shape;
    CubicKernel kernel;
    double relativeRms = 0.0;
    int iterations = 0;
    int evaluations = 0;
    int restarts = 0;
    std::vector<OptimizerStep> path;
};

/// @brief The Gaussian of a given extent whose σ minimizes the lattice r.m.s., normalized so the
/// mean of its reconstruction is 1.
struct GaussianFit {
    GaussianKernel kernel;
    double relativeRms = 0.0;
};

/// @brief Finds local minima of the relative r.m.s. deviation of the lattice reconstruction over
/// the paper's parametrization (Crawfis & Max 1993, section 2), with a gradient-free method.
///
/// The paper used a quasi-Newton method with finite-difference gradients [Gay83]. Here Nelder–Mead
/// runs on parameters scaled by the start (so b ≈ −2 and d ≈ 0.1 move in equal relative steps)
/// and restarts from its best point until a restart no longer improves it, which undoes the
/// simplex collapse that the badly conditioned valley of this objective causes. The objective is
/// LatticeAnalysis::relativeRms, exact up to rounding in long double, so neither finite
/// differences nor the simplex see quadrature noise. Points outside 0 < s < t are +∞.
///
/// The support is kept in (minSupport(), maxSupport()]: below, some points of the cell are out of
/// every kernel's reach, so the reconstruction is 0 there and no shape makes it flat (at t = 1e-6
/// the "optimized" kernel had a relative r.m.s. of 5.6e8); above, LatticeAnalysis bounds the run
/// time.
class KernelOptimizer {
public:
    /// @brief Reports one iteration group (for a progress line).
    using Progress = std::function<void(const OptimizerStep& step)>;

    /// @brief An optimizer with the given options. Throws DataError for a bad spacing
    /// (LatticeAnalysis::checkSpacing) or a fixed support outside (minSupport(), maxSupport()].
    explicit KernelOptimizer(const OptimizerOptions& options = {});

    /// @brief Half the cell diagonal, ½ √(sx² + sy² + sz²): a kernel's support must exceed it
    /// to reach every point of the cell (0.866 on the unit lattice).
    double minSupport() const;

    /// @brief The largest support on the lattice: LatticeAnalysis::maxSupport (4 on the unit
    /// lattice).
    double maxSupport() const;

    /// @brief The default start: round values near the paper's minimum
    /// (s = 0.9, t = 1.55, b = −2, d = 0.12), scaled to the fixed support and the spacing's
    /// geometric mean when those are set.
    KernelShape defaultStart() const;

    /// @brief The objective: relative r.m.s. deviation of the kernel with this shape on the
    /// lattice; +∞ outside the domain: non-finite values, a support outside (minSupport(),
    /// maxSupport()], ∫h ≤ 0, s closer than 0.1% of t to 0 or to t (where solving the C¹
    /// conditions degenerates), or a profile that increases somewhere
    /// (CubicKernel::isNonIncreasing; without it the relative measure, which ignores scale,
    /// drifts to ring-shaped kernels with b, d → ∞ on non-cubic lattices).
    double objective(const KernelShape& shape) const;

    /// @brief Minimizes from start. Throws DataError with a clear message when the start is not
    /// admissible (s ≤ 0, t ≤ s, non-finite values, s ≥ the fixed support, a free t outside
    /// (minSupport(), maxSupport()]) or lies outside the objective's domain (see objective()).
    OptimizerResult optimize(const KernelShape& start, const Progress& progress = {}) const;

    /// @brief The truncated Gaussian with the given support whose σ minimizes the relative r.m.s.
    /// on the lattice (a 1D Nelder–Mead from σ = t/3): the fairest Gaussian of the same extent.
    /// Throws DataError unless support lies in (minSupport(), maxSupport()].
    GaussianFit fitGaussian(double support) const;

private:
    bool isSupportInRange(double support) const;
    void requireSupportInRange(double support, const std::string& what) const;

    OptimizerOptions mOptions;
};

} // namespace texsplat::kernel
