#include "nodes/kernel/detail/GaussLegendre.h"

#include "scenegraph/Assert.h"

#include <cmath>

namespace texsplat::kernel::detail {

std::vector<QuadratureNode> gaussLegendreRule(int count) {
    TEXSPLAT_ASSERT(count > 0, "gaussLegendreRule(): count must be positive");
    const long double pi = std::acos(-1.0L);
    std::vector<QuadratureNode> rule(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        // Tricomi's estimate of the i-th root, then Newton on P_n (three-term recurrence).
        long double x = std::cos(pi * (i + 0.75L) / (count + 0.5L));
        long double derivative = 1.0L;
        for (int iteration = 0; iteration < 100; ++iteration) {
            long double previous = 1.0L;
            long double current = x;
            for (int degree = 2; degree <= count; ++degree) {
                const long double next =
                    ((2 * degree - 1) * x * current - (degree - 1) * previous) / degree;
                previous = current;
                current = next;
            }
            derivative = count * (x * current - previous) / (x * x - 1.0L);
            const long double step = current / derivative;
            x -= step;
            if (std::fabs(step) < 1e-19L)
                break;
        }
        rule[static_cast<size_t>(i)] = {x, 2.0L / ((1.0L - x * x) * derivative * derivative)};
    }
    return rule;
}

} // namespace texsplat::kernel::detail
