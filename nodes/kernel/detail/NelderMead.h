#pragma once

#include <functional>
#include <vector>

namespace texsplat::kernel::detail {

/// @brief Settings of one Nelder–Mead run.
struct NelderMeadOptions {
    std::vector<double> initialStep; ///< simplex edge per coordinate; also the scale of x
    double tolerance = 1e-10;        ///< stop when all vertices are this close (in steps) to the best
    int maxEvaluations = 20000;      ///< hard cap on objective evaluations
};

/// @brief The best point a Nelder–Mead run found.
struct NelderMeadResult {
    std::vector<double> point;
    double value = 0.0;
    int iterations = 0;
    int evaluations = 0;
    bool converged = false;
};

/// @brief The function to minimize; +∞ (or NaN) marks a point outside its domain.
using Objective = std::function<double(const std::vector<double>&)>;

/// @brief Called after every iteration with the iteration count, the best point and its value.
using NelderMeadObserver =
    std::function<void(int iteration, const std::vector<double>& best, double value)>;

/// @brief Minimizes objective from start with the Nelder–Mead simplex method (reflection 1,
/// expansion 2, contraction ½, shrink ½). Needs no gradient; an objective may return +∞ for
/// points outside its domain, which the simplex then treats as worst and contracts away from.
NelderMeadResult minimizeNelderMead(const Objective& objective,
                                    const std::vector<double>& start,
                                    const NelderMeadOptions& options,
                                    const NelderMeadObserver& observer = {});

} // namespace texsplat::kernel::detail
