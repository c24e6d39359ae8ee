#pragma once

#include "nodes/kernel/RadialKernel.h"

namespace texsplat::kernel {

/// @brief The coefficients of the paper's piecewise cubic: p(r) = a + b r² + c r³ on [0, s],
/// q(r) = d (t−r)² + e (t−r)³ on [s, t] (Crawfis & Max 1993, section 2).
struct CubicCoefficients {
    double a = 0.0; ///< p(0)
    double b = 0.0; ///< r² coefficient of p
    double c = 0.0; ///< r³ coefficient of p
    double d = 0.0; ///< (t−r)² coefficient of q
    double e = 0.0; ///< (t−r)³ coefficient of q
};

/// @brief The paper's reconstruction kernel g(r): a piecewise cubic with knot s and support t,
/// C¹ at 0 (no linear term in p), at s (p and q meet with equal slopes) and at t (q has a double
/// root there), and its footprint in closed form.
///
/// The footprint f(r) = 2 ∫₀^√(t²−r²) g(√(r²+z²)) dz is a sum of chord moments
/// ∫ ρⁿ dz (ρ = √(r²+z²)), which are polynomials in z and ρ plus r²·asinh(z/r) terms. Expanded
/// naively they cancel: near r = t the outer piece is O((t−r)^{5/2}) but is computed from O(1)
/// terms. The outer piece is therefore written as r^{k+1} φₖ(√(t²−r²)/r) with φₖ evaluated by
/// its Taylor series when the argument is small; asinh(z/r) is taken as log(z+R) − log(r) so that
/// subnormal r neither overflows nor produces 0·∞ (docs/kernel.md derives every form).
class CubicKernel final : public RadialKernel {
public:
    /// @brief The kernel exactly as printed in the paper: t = 1.556228, s = 0.889392,
    /// 0.557526 − 1.157743 r² + 0.671033 r³ ; 0.067599 (t−r)² + 0.282474 (t−r)³.
    static CubicKernel paper();

    /// @brief The paper's parametrization: a = 1, free s, t, b, d; c and e are solved from the C¹
    /// conditions at s. Throws DataError unless 0 < s < t and all values are finite.
    static CubicKernel fromShape(double knot, double support, double b, double d);

    /// @brief A kernel with the given knot s, support t and coefficients (used as given, so a
    /// printed kernel keeps its rounding). Throws DataError unless 0 < s < t and every value is
    /// finite.
    CubicKernel(double knot, double support, const CubicCoefficients& coefficients);

    /// @brief The same shape with every coefficient multiplied by factor (the paper divides by the
    /// mean of the reconstruction to normalize). Throws DataError if factor is not finite.
    CubicKernel scaled(double factor) const;

    /// @brief The knot s where p and q meet.
    double knot() const { return mKnot; }

    /// @brief The coefficients a, b, c, d, e.
    const CubicCoefficients& coefficients() const { return mCoefficients; }

    /// @brief Whether g never increases on [0, t], as a low-pass reconstruction kernel should:
    /// p'(r) = r(2b + 3cr) ≤ 0 on [0, s] and q'(r) = −u(2d + 3eu) ≤ 0 for u = t − r ∈ [0, t−s];
    /// both brackets are linear, so checking their ends decides it.
    bool isNonIncreasing() const;

    /// @brief g'(r) for r ≥ 0 (p' below the knot, q' from the knot on, 0 beyond the support).
    double derivative(double r) const;

    long double profile(long double r) const override;
    long double shellIntegral(long double r) const override;
    double footprint(double r) const override;
    double support() const override { return mSupport; }
    std::vector<double> breakpoints() const override { return {mKnot}; }
    /// @brief +∞: g·r·W and g²r² are polynomials of degree ≤ 9 between the breakpoints.
    double quadratureStep() const override;
    std::string description() const override;

private:
    double mKnot;
    double mSupport;
    CubicCoefficients mCoefficients;
};

} // namespace texsplat::kernel
