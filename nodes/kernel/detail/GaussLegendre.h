#pragma once

#include <vector>

namespace texsplat::kernel::detail {

/// @brief One node of a quadrature rule on [−1, 1].
struct QuadratureNode {
    long double position;
    long double weight;
};

/// @brief The n-point Gauss–Legendre rule on [−1, 1] in long double (exact for polynomials of
/// degree 2n−1), computed by Newton's iteration on the Legendre polynomial.
std::vector<QuadratureNode> gaussLegendreRule(int count);

/// @brief ∫ₐᵇ integrand(x) dx with the given rule mapped onto [a, b].
template <typename Integrand>
long double integrate(const std::vector<QuadratureNode>& rule, long double a, long double b,
                      const Integrand& integrand) {
    const long double half = 0.5L * (b - a);
    const long double middle = 0.5L * (a + b);
    long double sum = 0.0L;
    for (const QuadratureNode& node : rule)
        sum += node.weight * integrand(middle + half * node.position);
    return sum * half;
}

} // namespace texsplat::kernel::detail
