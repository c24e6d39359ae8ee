#pragma once

#include <string>
#include <vector>

namespace texsplat::kernel {

/// @brief A rotationally symmetric 3D reconstruction kernel h(x,y,z) = g(|(x,y,z)|) with finite
/// support t (Crawfis & Max 1993, section 2), and its 2D footprint f(r) = ∫ g(√(r²+z²)) dz
/// (the paper's equation 1).
///
/// Kernels are expressed in voxel units (voxel centres on the integer lattice) unless a lattice
/// spacing says otherwise. The profile and its shell integral are evaluated in long double: the
/// lattice analysis forms the variance of the reconstruction as a difference of sums that agree
/// to about six digits, and extended precision keeps the optimizer's objective free of rounding
/// noise. The footprint is evaluated in double with forms that are stable for every r.
class RadialKernel {
public:
    virtual ~RadialKernel() = default;

    /// @brief g(r) for r ≥ 0: the kernel at distance r from its centre; 0 for r ≥ support().
    virtual long double profile(long double r) const = 0;

    /// @brief W(r) = ∫₀^min(r,t) g(ρ) ρ dρ, the closed-form antiderivative the lattice analysis
    /// uses to integrate g over spherical shells (r ≥ 0).
    virtual long double shellIntegral(long double r) const = 0;

    /// @brief f(r) = ∫ g(√(r²+z²)) dz, the footprint at distance r from the splat centre.
    ///
    /// Even in r (f(−r) = f(r)); exactly 0 for |r| ≥ support() and for infinite r; NaN for NaN.
    virtual double footprint(double r) const = 0;

    /// @brief The support radius t: g(r) = 0 for r ≥ t.
    virtual double support() const = 0;

    /// @brief Radii in (0, t) where g or one of its first few derivatives is not smooth (the
    /// knot s of a piecewise kernel); quadrature splits its intervals there.
    virtual std::vector<double> breakpoints() const = 0;

    /// @brief The longest piece, between breakpoints, on which ten-point Gauss–Legendre
    /// integrates g times its shell integral (and polynomials of r) to rounding: +∞ where
    /// those products are polynomials of degree ≤ 19 (integrated exactly on any interval), else
    /// a length on the kernel's own scale, so the lattice analysis needs the same number of
    /// pieces in any unit of length.
    virtual double quadratureStep() const = 0;

    /// @brief A short human-readable description ("paper cubic, t = 1.556228, s = 0.889392").
    virtual std::string description() const = 0;

    /// @brief g(r) in double, even in r, 0 outside the support; a convenience for plots and
    /// textures.
    double value(double r) const;
};

} // namespace texsplat::kernel
