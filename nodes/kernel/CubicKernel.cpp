#include "nodes/kernel/CubicKernel.h"

#include "scenegraph/Error.h"

#include <array>
#include <cmath>
#include <sstream>

namespace texsplat::kernel {

namespace {

// The paper's printed kernel (Crawfis & Max 1993, section 2).
constexpr double kPaperSupport = 1.556228;
constexpr double kPaperKnot = 0.889392;
constexpr CubicCoefficients kPaperCoefficients{0.557526, -1.157743, 0.671033, 0.067599, 0.282474};

// Below this w = √(t²−r²)/r the closed forms of the outer chord moments lose more than about
// 1/w⁶ ≈ 64 ulps to cancellation, so the Taylor series takes over; 28 terms of the series (radius
// of convergence 1) leave a truncation error below 0.25²⁸ ≈ 1e-17 relative.
constexpr double kSeriesThreshold = 0.5;

// Taylor coefficients of φ₂(w) = w + w³/3 − √(1+w²)·asinh(w) = w⁵ Σ kPhi2[i] w^{2i} and
// φ₃(w) = (w√(1+w²)(2w²+15) − 3(4w²+5)·asinh(w))/8 = w⁷ Σ kPhi3[i] w^{2i}. They are rationals
// (2/15, −8/105, 16/315, … and 2/35, −1/21, 5/132, …) from a computer-algebra expansion,
// rounded to double; docs/kernel.md has the derivation and the script.
constexpr std::array<double, 28> kPhi2{
    0.13333333333333333, -0.076190476190476197, 0.050793650793650794,
    -0.036940836940836941, 0.028416028416028416, -0.022732822732822733,
    0.01872114813291284, -0.015765177375084496, 0.013513009178643854,
    -0.011750442764038133, 0.010340389632353557, -0.0091914574509809402,
    0.0082406170250173948, -0.007443137958080227, 0.0067664890528002066,
    -0.0061865042768459036, 0.0056848958219665058, -0.0052475961433536972,
    0.0048636256938400122, -0.0045243029710139646, 0.0042226827729463677,
    -0.0039531498299923435, 0.0037111202485642413, -0.0034928190574722269,
    0.0032951123183700254, -0.0031153789191862057, 0.0029514116076500897,
    -0.0028013398309899157};
constexpr std::array<double, 28> kPhi3{
    0.057142857142857141, -0.047619047619047616, 0.03787878787878788,
    -0.030594405594405596, 0.025240384615384616, -0.021231617647058824,
    0.018158620356037151, -0.01574982377819549, 0.013823894240100932,
    -0.012257186226222827, 0.010963372124565973, -0.0098807820871872013,
    0.008964419232327098, -0.0081808161525782248, 0.0075046466542528821,
    -0.0069164446191898182, 0.0064010364865098078, -0.0059464435079126261,
    0.0055430994715232043, -0.0051832842426699438, 0.0048607075105463349,
    -0.004570198752627385, 0.0043074734232651157, -0.0040689545913779991,
    0.0038516354257021285, -0.0036529721247974926, 0.0034707997861097425,
    -0.0033032657345033528};

double evenSeries(const std::array<double, 28>& coefficients, double wSquared) {
    double sum = 0.0;
    for (auto it = coefficients.rbegin(); it != coefficients.rend(); ++it)
        sum = sum * wSquared + *it;
    return sum;
}

// r²·asinh(z/r) written as r²·(log(z+R) − log r), R = √(r²+z²): finite for subnormal r, and
// exactly 0 at r = 0 (its limit).
double radiusSquaredTimesAsinh(double r, double z, double radius) {
    if (r == 0.0)
        return 0.0;
    return r * r * (std::log(z + radius) - std::log(r));
}

// ∫₀^z ρⁿ dz for n = 0..3 along a chord at distance r from the centre, ρ = √(r²+z²), where the
// chord ends on the sphere of the given radius (radius² = r² + z²). Every term is non-negative,
// so these sums do not cancel.
struct ChordMoments {
    double m0, m1, m2, m3;
};

ChordMoments chordMoments(double r, double z, double radius) {
    const double r2 = r * r;
    const double r2Asinh = radiusSquaredTimesAsinh(r, z, radius);
    return {z, 0.5 * (z * radius + r2Asinh), r2 * z + z * z * z / 3.0,
            z * radius * radius * radius / 4.0 + 3.0 * r2 * z * radius / 8.0 +
                3.0 * r2 * r2Asinh / 8.0};
}

// ∫₀^z q(ρ) dz for a chord ending on the sphere ρ = s < t, from the binomial expansion of
// (t−ρ)² and (t−ρ)³; t − ρ ≥ t − s there, so the expansion does not cancel badly.
double outerPartialChord(const CubicCoefficients& k, double t, const ChordMoments& m) {
    const double square = t * t * m.m0 - 2.0 * t * m.m1 + m.m2;
    const double cube = t * t * t * m.m0 - 3.0 * t * t * m.m1 + 3.0 * t * m.m2 - m.m3;
    return k.d * square + k.e * cube;
}

// ∫₀^Z q(ρ) dz for the whole half chord, Z = √(t²−r²). In closed form
// ∫(t−ρ)² dz = Z(t²+2r²)/3 − t r² asinh(Z/r) and
// ∫(t−ρ)³ dz = Z t³/4 + 13 t r² Z/8 − 3 r² (4t²+r²) asinh(Z/r)/8,
// which equal r³ φ₂(Z/r) and r⁴ φ₃(Z/r); for small Z/r (r near t) the series of φ is used.
double outerFullChord(const CubicCoefficients& k, double r, double t, double halfChord) {
    if (r > 0.0 && halfChord < kSeriesThreshold * r) {
        const double w = halfChord / r;
        const double w2 = w * w;
        const double r3w5 = r * r * r * w2 * w2 * w;
        return k.d * r3w5 * evenSeries(kPhi2, w2) + k.e * r3w5 * r * w2 * evenSeries(kPhi3, w2);
    }
    const double r2 = r * r;
    const double r2Asinh = radiusSquaredTimesAsinh(r, halfChord, t);
    const double square = halfChord * (t * t + 2.0 * r2) / 3.0 - t * r2Asinh;
    const double cube = halfChord * t * t * t / 4.0 + 13.0 * t * r2 * halfChord / 8.0 -
                        3.0 * (4.0 * t * t + r2) * r2Asinh / 8.0;
    return k.d * square + k.e * cube;
}

void requireFinite(double value, const char* name) {
    if (!std::isfinite(value)) {
        std::ostringstream message;
        message << "cubic kernel: " << name << " = " << value << " is not finite";
        throw DataError(message.str());
    }
}

} // namespace

CubicKernel CubicKernel::paper() {
    return CubicKernel(kPaperKnot, kPaperSupport, kPaperCoefficients);
}

CubicKernel CubicKernel::fromShape(double knot, double support, double b, double d) {
    requireFinite(b, "b");
    requireFinite(d, "d");
    CubicKernel kernel(knot, support, CubicCoefficients{1.0, b, 0.0, d, 0.0});
    // C¹ at s (section 2): p(s) = q(s) and p'(s) = q'(s) are linear in c and e:
    //   s³ c − u³ e = d u² − 1 − b s²,   3 s² c + 3 u² e = −2 d u − 2 b s,   u = t − s.
    const double s = knot;
    const double u = support - knot;
    const double rhsValue = d * u * u - 1.0 - b * s * s;
    const double rhsSlope = -2.0 * d * u - 2.0 * b * s;
    const double determinant = 3.0 * s * s * u * u * (s + u);
    kernel.mCoefficients.c = (rhsValue * 3.0 * u * u + u * u * u * rhsSlope) / determinant;
    kernel.mCoefficients.e = (s * s * s * rhsSlope - 3.0 * s * s * rhsValue) / determinant;
    return kernel;
}

CubicKernel::CubicKernel(double knot, double support, const CubicCoefficients& coefficients)
    : mKnot(knot), mSupport(support), mCoefficients(coefficients) {
    requireFinite(knot, "knot s");
    requireFinite(support, "support t");
    requireFinite(coefficients.a, "a");
    requireFinite(coefficients.b, "b");
    requireFinite(coefficients.c, "c");
    requireFinite(coefficients.d, "d");
    requireFinite(coefficients.e, "e");
    if (!(knot > 0.0)) {
        std::ostringstream message;
        message << "cubic kernel: knot s = " << knot << " must be > 0";
        throw DataError(message.str());
    }
    if (!(support > knot)) {
        std::ostringstream message;
        message << "cubic kernel: support t = " << support << " must be > knot s = " << knot;
        throw DataError(message.str());
    }
}

CubicKernel CubicKernel::scaled(double factor) const {
    requireFinite(factor, "scale factor");
    const CubicCoefficients& k = mCoefficients;
    return CubicKernel(mKnot, mSupport,
                       {k.a * factor, k.b * factor, k.c * factor, k.d * factor, k.e * factor});
}

bool CubicKernel::isNonIncreasing() const {
    const CubicCoefficients& k = mCoefficients;
    const double u = mSupport - mKnot;
    return k.b <= 0.0 && 2.0 * k.b + 3.0 * k.c * mKnot <= 0.0 && k.d >= 0.0 &&
           2.0 * k.d + 3.0 * k.e * u >= 0.0;
}

double CubicKernel::derivative(double r) const {
    const CubicCoefficients& k = mCoefficients;
    if (r >= mSupport)
        return 0.0;
    if (r < mKnot)
        return r * (2.0 * k.b + 3.0 * k.c * r);
    const double u = mSupport - r;
    return -u * (2.0 * k.d + 3.0 * k.e * u);
}

long double CubicKernel::profile(long double r) const {
    const CubicCoefficients& k = mCoefficients;
    if (r >= mSupport)
        return 0.0L;
    if (r < mKnot)
        return k.a + r * r * (k.b + k.c * r);
    const long double u = mSupport - r;
    return u * u * (k.d + k.e * u);
}

long double CubicKernel::shellIntegral(long double r) const {
    const CubicCoefficients& k = mCoefficients;
    const long double s = mKnot;
    const long double t = mSupport;
    const auto inner = [&](long double x) {
        const long double x2 = x * x;
        return x2 * (k.a / 2.0L + x2 * (k.b / 4.0L + k.c * x / 5.0L));
    };
    if (r <= s)
        return inner(r);
    // ∫ q(ρ) ρ dρ in u = t − ρ: ∫ (d u² + e u³)(t − u) du = Φ(u), integrated from t−r to t−s.
    const auto outer = [&](long double u) {
        const long double u3 = u * u * u;
        return u3 * (k.d * t / 3.0L + u * ((k.e * t - k.d) / 4.0L - k.e * u / 5.0L));
    };
    const long double uEnd = r >= t ? 0.0L : t - r;
    return inner(s) + outer(t - s) - outer(uEnd);
}

double CubicKernel::footprint(double r) const {
    if (std::isnan(r))
        return r;
    r = std::fabs(r);
    const double s = mKnot;
    const double t = mSupport;
    if (r >= t)
        return 0.0;
    // (t−r)(t+r) rather than t²−r²: no cancellation as r → t (likewise for s).
    const double halfChord = std::sqrt((t - r) * (t + r));
    const double outer = outerFullChord(mCoefficients, r, t, halfChord);
    if (r >= s)
        return 2.0 * outer;
    const double innerHalfChord = std::sqrt((s - r) * (s + r));
    const ChordMoments m = chordMoments(r, innerHalfChord, s);
    const CubicCoefficients& k = mCoefficients;
    const double inner = k.a * m.m0 + k.b * m.m2 + k.c * m.m3;
    return 2.0 * (inner + outer - outerPartialChord(k, t, m));
}

double CubicKernel::quadratureStep() const { return HUGE_VAL; }

std::string CubicKernel::description() const {
    std::ostringstream text;
    text.precision(7);
    text << "piecewise cubic, s = " << mKnot << ", t = " << mSupport;
    return text.str();
}

} // namespace texsplat::kernel
