#include "nodes/kernel/GaussianKernel.h"

#include "scenegraph/Error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace texsplat::kernel {

namespace {
constexpr double kSqrtTwoPi = 2.50662827463100050242;
constexpr double kSqrtTwo = 1.41421356237309504880;
} // namespace

GaussianKernel::GaussianKernel(double sigma, double support, double amplitude)
    : mSigma(sigma), mSupport(support), mAmplitude(amplitude) {
    const auto require = [](bool valid, const char* name, double value, const char* expected) {
        if (!valid) {
            std::ostringstream message;
            message << "gaussian kernel: " << name << " = " << value << " must be " << expected;
            throw DataError(message.str());
        }
    };
    require(std::isfinite(sigma) && sigma > 0.0, "sigma", sigma, "a finite number > 0");
    require(std::isfinite(support) && support > 0.0, "support t", support, "a finite number > 0");
    require(std::isfinite(amplitude), "amplitude", amplitude, "finite");
}

GaussianKernel GaussianKernel::scaled(double factor) const {
    return GaussianKernel(mSigma, mSupport, mAmplitude * factor);
}

long double GaussianKernel::profile(long double r) const {
    if (r >= mSupport)
        return 0.0L;
    const long double sigma = mSigma;
    return mAmplitude * std::exp(-r * r / (2.0L * sigma * sigma));
}

long double GaussianKernel::shellIntegral(long double r) const {
    // ∫₀^r A e^{−ρ²/(2σ²)} ρ dρ = −A σ² expm1(−r²/(2σ²)); expm1 keeps small r accurate.
    const long double end = std::min<long double>(r, mSupport);
    const long double sigma = mSigma;
    return -mAmplitude * sigma * sigma * std::expm1(-end * end / (2.0L * sigma * sigma));
}

double GaussianKernel::footprint(double r) const {
    if (std::isnan(r))
        return r;
    r = std::fabs(r);
    if (r >= mSupport)
        return 0.0;
    const double halfChord = std::sqrt((mSupport - r) * (mSupport + r));
    return mAmplitude * std::exp(-r * r / (2.0 * mSigma * mSigma)) * mSigma * kSqrtTwoPi *
           std::erf(halfChord / (mSigma * kSqrtTwo));
}

double GaussianKernel::quadratureStep() const {
    return std::max(0.5 * mSigma, mSupport / 4096.0);
}

std::string GaussianKernel::description() const {
    std::ostringstream text;
    text.precision(7);
    text << "truncated gaussian, sigma = " << mSigma << ", t = " << mSupport;
    return text.str();
}

} // namespace texsplat::kernel
