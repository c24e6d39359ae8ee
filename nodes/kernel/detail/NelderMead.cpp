#include "nodes/kernel/detail/NelderMead.h"

#include "scenegraph/Assert.h"

#include <algorithm>
#include <cmath>

namespace texsplat::kernel::detail {

namespace {

struct Vertex {
    std::vector<double> point;
    double value;
};

// x + factor·(y − x), coordinate by coordinate.
std::vector<double> towards(const std::vector<double>& x, const std::vector<double>& y,
                            double factor) {
    std::vector<double> result(x.size());
    for (size_t i = 0; i < x.size(); ++i)
        result[i] = x[i] + factor * (y[i] - x[i]);
    return result;
}

} // namespace

NelderMeadResult minimizeNelderMead(const Objective& objective,
                                    const std::vector<double>& start,
                                    const NelderMeadOptions& options,
                                    const NelderMeadObserver& observer) {
    const size_t n = start.size();
    TEXSPLAT_ASSERT(n > 0 && options.initialStep.size() == n,
                    "minimizeNelderMead(): one initial step per coordinate");
    NelderMeadResult result;
    const auto evaluate = [&](const std::vector<double>& point) {
        ++result.evaluations;
        const double value = objective(point);
        return std::isnan(value) ? HUGE_VAL : value;
    };
    std::vector<Vertex> simplex;
    simplex.push_back({start, evaluate(start)});
    for (size_t i = 0; i < n; ++i) {
        std::vector<double> point = start;
        point[i] += options.initialStep[i];
        simplex.push_back({point, evaluate(point)});
    }
    const auto byValue = [](const Vertex& a, const Vertex& b) { return a.value < b.value; };
    while (true) {
        std::sort(simplex.begin(), simplex.end(), byValue);
        const Vertex& best = simplex.front();
        double spread = 0.0;
        for (const Vertex& vertex : simplex)
            for (size_t i = 0; i < n; ++i)
                spread = std::max(spread, std::fabs(vertex.point[i] - best.point[i]) /
                                              std::fabs(options.initialStep[i]));
        if (observer)
            observer(result.iterations, best.point, best.value);
        if (spread < options.tolerance) {
            result.converged = true;
            break;
        }
        if (result.evaluations >= options.maxEvaluations)
            break;
        ++result.iterations;
        std::vector<double> centroid(n, 0.0);
        for (size_t v = 0; v < n; ++v)
            for (size_t i = 0; i < n; ++i)
                centroid[i] += simplex[v].point[i] / static_cast<double>(n);
        Vertex& worst = simplex.back();
        const Vertex reflected{towards(centroid, worst.point, -1.0), 0.0};
        const double reflectedValue = evaluate(reflected.point);
        if (reflectedValue < simplex.front().value) {
            std::vector<double> expanded = towards(centroid, worst.point, -2.0);
            const double expandedValue = evaluate(expanded);
            worst = expandedValue < reflectedValue ? Vertex{expanded, expandedValue}
                                                   : Vertex{reflected.point, reflectedValue};
            continue;
        }
        if (reflectedValue < simplex[n - 1].value) {
            worst = {reflected.point, reflectedValue};
            continue;
        }
        // Contract towards the better of the worst vertex and its reflection.
        const bool outside = reflectedValue < worst.value;
        std::vector<double> contracted =
            towards(centroid, outside ? reflected.point : worst.point, 0.5);
        const double contractedValue = evaluate(contracted);
        if (contractedValue < std::min(reflectedValue, worst.value)) {
            worst = {contracted, contractedValue};
            continue;
        }
        for (size_t v = 1; v <= n; ++v) {
            simplex[v].point = towards(simplex.front().point, simplex[v].point, 0.5);
            simplex[v].value = evaluate(simplex[v].point);
        }
    }
    result.point = simplex.front().point;
    result.value = simplex.front().value;
    return result;
}

} // namespace texsplat::kernel::detail
