#include "nodes/kernel/KernelOptimizer.h"

#include "nodes/kernel/detail/NelderMead.h"
#include "scenegraph/Error.h"

#include <cmath>
#include <sstream>

namespace texsplat::kernel {

namespace {

// A round start near the paper's minimum (t = 1.556228, s = 0.889392, b/a = −2.0766,
// d/a = 0.1212), in voxel units.
constexpr KernelShape kRoundStart{0.9, 1.55, -2.0, 0.12};

// Each restart's simplex spans 5% of every parameter; a run stops when all vertices agree with
// the best to 1e-9 of that (≈ 5e-11 relative), and restarts stop when one no longer lowers the
// objective by more than kImprovement relative.
constexpr double kRelativeStep = 0.05;
constexpr double kSimplexTolerance = 1e-9;
constexpr double kImprovement = 1e-13;

// The C¹ conditions at s are solved with the determinant 3 s² (t−s)² t, so as s approaches 0 or t
// the coefficients c, e grow like 1/s³ or 1/(t−s)³ and the kernel degenerates into a step. The
// search stays where s is at least this fraction of t away from both ends.
constexpr double kKnotMargin = 1e-3;

void requireAdmissible(const KernelShape& start, const std::optional<double>& fixedSupport) {
    const auto fail = [](const std::string& what) {
        throw DataError("optimizer start: " + what);
    };
    const std::pair<const char*, double> values[] = {
        {"knot s", start.knot}, {"support t", start.support}, {"b", start.b}, {"d", start.d}};
    for (const auto& [name, value] : values) {
        if (!std::isfinite(value)) {
            std::ostringstream message;
            message << name << " = " << value << " is not finite";
            fail(message.str());
        }
    }
    std::ostringstream message;
    const double support = fixedSupport.value_or(start.support);
    if (!(start.knot > 0.0)) {
        message << "knot s = " << start.knot << " must be > 0";
        fail(message.str());
    }
    if (!(support > start.knot)) {
        message << "support t = " << support << " must be > knot s = " << start.knot;
        fail(message.str());
    }
}

} // namespace

KernelOptimizer::KernelOptimizer(const OptimizerOptions& options) : mOptions(options) {
    LatticeAnalysis::checkSpacing(options.spacing);
    if (options.fixedSupport)
        requireSupportInRange(*options.fixedSupport, "kernel support");
}

double KernelOptimizer::minSupport() const {
    const LatticeSpacing& spacing = mOptions.spacing;
    return 0.5 * std::sqrt(spacing[0] * spacing[0] + spacing[1] * spacing[1] +
                           spacing[2] * spacing[2]);
}

double KernelOptimizer::maxSupport() const { return LatticeAnalysis::maxSupport(mOptions.spacing); }

bool KernelOptimizer::isSupportInRange(double support) const {
    return support > minSupport() && support <= maxSupport();
}

void KernelOptimizer::requireSupportInRange(double support, const std::string& what) const {
    if (isSupportInRange(support))
        return;
    std::ostringstream message;
    message << what << " " << support << " must be in (" << minSupport() << ", " << maxSupport()
            << "] on lattice spacing " << spacingText(mOptions.spacing)
            << ": more than half the cell diagonal (or some points are out of every kernel's "
               "reach) and at most "
            << LatticeAnalysis::kMaxSupportInCellSizes
            << " times the cube root of the cell volume (the run time grows as t³ over the "
               "volume)";
    throw DataError(message.str());
}

KernelShape KernelOptimizer::defaultStart() const {
    const LatticeSpacing& spacing = mOptions.spacing;
    const double length = std::cbrt(spacing[0] * spacing[1] * spacing[2]);
    const double scale = mOptions.fixedSupport ? *mOptions.fixedSupport / kRoundStart.support
                                               : length;
    // g(r/L) keeps a = 1 and scales the r² and (t−r)² coefficients by 1/L².
    return {kRoundStart.knot * scale, kRoundStart.support * scale, kRoundStart.b / (scale * scale),
            kRoundStart.d / (scale * scale)};
}

double KernelOptimizer::objective(const KernelShape& shape) const {
    const double support = mOptions.fixedSupport.value_or(shape.support);
    if (!(std::isfinite(shape.knot) && isSupportInRange(support) && std::isfinite(shape.b) &&
          std::isfinite(shape.d) && shape.knot >= kKnotMargin * support &&
          shape.knot <= (1.0 - kKnotMargin) * support))
        return HUGE_VAL;
    const CubicKernel kernel = CubicKernel::fromShape(shape.knot, support, shape.b, shape.d);
    if (!kernel.isNonIncreasing())
        return HUGE_VAL;
    return LatticeAnalysis(kernel, mOptions.spacing).relativeRms();
}

OptimizerResult KernelOptimizer::optimize(const KernelShape& start,
                                          const Progress& progress) const {
    requireAdmissible(start, mOptions.fixedSupport);
    const bool freeSupport = !mOptions.fixedSupport;
    if (freeSupport)
        requireSupportInRange(start.support, "optimizer start: support t =");
    // Work in x = parameter / |start parameter|, so every coordinate is O(1).
    const auto toVector = [&](const KernelShape& shape) {
        return freeSupport ? std::vector<double>{shape.knot, shape.support, shape.b, shape.d}
                           : std::vector<double>{shape.knot, shape.b, shape.d};
    };
    std::vector<double> scale = toVector(start);
    for (double& value : scale)
        value = value == 0.0 ? 1.0 : std::fabs(value);
    const auto toShape = [&](const std::vector<double>& x) {
        if (freeSupport)
            return KernelShape{x[0] * scale[0], x[1] * scale[1], x[2] * scale[2], x[3] * scale[3]};
        return KernelShape{x[0] * scale[0], *mOptions.fixedSupport, x[1] * scale[1],
                           x[2] * scale[2]};
    };
    std::vector<double> x = toVector(start);
    for (size_t i = 0; i < x.size(); ++i)
        x[i] /= scale[i];
    KernelShape best = toShape(x);
    double bestValue = objective(best);
    if (!std::isfinite(bestValue))
        throw DataError("optimizer start: outside the search domain (the profile must not "
                        "increase, and s must lie within [0.001 t, 0.999 t])");
    std::vector<OptimizerStep> path;
    int iterations = 0;
    int evaluations = 0;
    int restarts = 0;
    detail::NelderMeadOptions options;
    options.initialStep.assign(x.size(), kRelativeStep);
    options.tolerance = kSimplexTolerance;
    for (int attempt = 0; attempt <= mOptions.maxRestarts; ++attempt) {
        options.maxEvaluations = mOptions.maxEvaluations - evaluations;
        if (options.maxEvaluations <= 0)
            break;
        restarts = attempt;
        const auto observer = [&](int iteration, const std::vector<double>& point, double value) {
            if (iteration % mOptions.progressInterval != 0)
                return;
            path.push_back({restarts, iterations + iteration, evaluations, toShape(point), value});
            if (progress)
                progress(path.back());
        };
        const detail::NelderMeadResult run = detail::minimizeNelderMead(
            [&](const std::vector<double>& point) {
                ++evaluations;
                return objective(toShape(point));
            },
            x, options, observer);
        iterations += run.iterations;
        const bool improved = run.value < bestValue * (1.0 - kImprovement);
        if (run.value < bestValue) {
            bestValue = run.value;
            best = toShape(run.point);
            x = run.point;
        }
        if (!improved && attempt > 0)
            break;
    }
    path.push_back({restarts, iterations, evaluations, best, bestValue});
    const CubicKernel unnormalized = CubicKernel::fromShape(best.knot, best.support, best.b, best.d);
    const LatticeSpacing& spacing = mOptions.spacing;
    const double mean = LatticeAnalysis(unnormalized, spacing).volumeIntegral() /
                        (spacing[0] * spacing[1] * spacing[2]);
    return {best,       unnormalized.scaled(1.0 / mean), bestValue, iterations, evaluations,
            restarts, std::move(path)};
}

GaussianFit KernelOptimizer::fitGaussian(double support) const {
    requireSupportInRange(support, "kernel support");
    const GaussianKernel start(support / 3.0, support);
    const LatticeSpacing& spacing = mOptions.spacing;
    const auto relativeRms = [&](const std::vector<double>& sigma) {
        if (!(sigma[0] > 0.0))
            return HUGE_VAL;
        const GaussianKernel kernel(sigma[0], support);
        return LatticeAnalysis(kernel, spacing).relativeRms();
    };
    detail::NelderMeadOptions options;
    options.initialStep = {kRelativeStep * start.sigma()};
    options.tolerance = kSimplexTolerance;
    const detail::NelderMeadResult best =
        detail::minimizeNelderMead(relativeRms, {start.sigma()}, options);
    const GaussianKernel unnormalized(best.point[0], support);
    const double mean = LatticeAnalysis(unnormalized, spacing).volumeIntegral() /
                        (spacing[0] * spacing[1] * spacing[2]);
    return {unnormalized.scaled(1.0 / mean), best.value};
}

} // namespace texsplat::kernel

