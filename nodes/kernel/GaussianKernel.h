#pragma once

#include "nodes/kernel/RadialKernel.h"

namespace texsplat::kernel {

/// @brief A Gaussian g(r) = A·exp(−r²/(2σ²)) truncated at the support t, for comparison with the
/// paper's cubic (the paper's baseline splats are Gaussians, section 4).
///
/// Truncation makes g jump from A·exp(−t²/(2σ²)) to 0 at t, so unlike the cubic it is not even
/// continuous there; with the same extent it must trade that jump against overlap. Its footprint
/// is closed form: f(r) = A·exp(−r²/(2σ²))·σ√(2π)·erf(√(t²−r²)/(σ√2)).
class GaussianKernel final : public RadialKernel {
public:
    /// @brief A Gaussian of standard deviation sigma and amplitude A, cut off at support. Throws
    /// DataError unless sigma and support are finite and positive and amplitude is finite.
    GaussianKernel(double sigma, double support, double amplitude = 1.0);

    /// @brief The same Gaussian with the amplitude multiplied by factor.
    GaussianKernel scaled(double factor) const;

    /// @brief The standard deviation σ.
    double sigma() const { return mSigma; }

    /// @brief The amplitude A = g(0).
    double amplitude() const { return mAmplitude; }

    long double profile(long double r) const override;
    long double shellIntegral(long double r) const override;
    double footprint(double r) const override;
    double support() const override { return mSupport; }
    std::vector<double> breakpoints() const override { return {}; }
    /// @brief σ/2 (the lattice analysis used 0.25 voxels, 0.45σ, for the best Gaussian of the
    /// paper's extent), but no shorter than t/4096, which bounds the work for needle-thin σ.
    double quadratureStep() const override;
    std::string description() const override;

private:
    double mSigma;
    double mSupport;
    double mAmplitude;
};

} // namespace texsplat::kernel
