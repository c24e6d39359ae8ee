#pragma once

// Reference integrals for the kernel tests: adaptive Gauss–Legendre in long double, independent
// of the closed forms under test.

#include "nodes/kernel/RadialKernel.h"
#include "nodes/kernel/detail/GaussLegendre.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace texsplat::test {

/// @brief ∫ₐᵇ integrand by bisection until two levels agree to tolerance (absolute) or to the
/// rounding level of long double, whichever is larger.
template <typename Integrand>
long double adaptiveIntegral(const Integrand& integrand, long double a, long double b,
                             long double tolerance, int depth = 30) {
    static const auto rule = kernel::detail::gaussLegendreRule(10);
    const long double middle = 0.5L * (a + b);
    const long double whole = kernel::detail::integrate(rule, a, b, integrand);
    const long double halves = kernel::detail::integrate(rule, a, middle, integrand) +
                               kernel::detail::integrate(rule, middle, b, integrand);
    const long double roundingLevel = 64.0L * LDBL_EPSILON * std::fabs(halves);
    if (std::fabs(halves - whole) <= std::max(tolerance, roundingLevel) || depth == 0)
        return halves;
    return adaptiveIntegral(integrand, a, middle, 0.5L * tolerance, depth - 1) +
           adaptiveIntegral(integrand, middle, b, 0.5L * tolerance, depth - 1);
}

/// @brief The footprint f(r) = ∫ g(√(r²+z²)) dz by adaptive quadrature in long double, split
/// where the chord crosses the kernel's breakpoints.
inline long double referenceFootprint(const kernel::RadialKernel& kernel, long double r) {
    const long double t = kernel.support();
    if (r >= t)
        return 0.0L;
    const auto integrand = [&](long double z) { return kernel.profile(std::sqrt(r * r + z * z)); };
    long double start = 0.0L;
    long double sum = 0.0L;
    for (double breakpoint : kernel.breakpoints()) {
        if (r >= breakpoint)
            continue;
        const long double end = std::sqrt((breakpoint - r) * (breakpoint + r));
        sum += adaptiveIntegral(integrand, start, end, 1e-18L);
        start = end;
    }
    sum += adaptiveIntegral(integrand, start, std::sqrt((t - r) * (t + r)), 1e-18L);
    return 2.0L * sum;
}

} // namespace texsplat::test
