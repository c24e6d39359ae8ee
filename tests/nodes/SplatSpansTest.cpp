// render::cpu::compositeSplats(), the CPU backend's SIMD inner loop, against its scalar
// reference (SplatSpansReference.h) on the splats `texsplat bench` draws: the same image within
// 1e-5 (relative, see kRelativeTolerance) for every footprint lookup, camera, medium and depth
// test the loop branches on, drawn in bands of rows as CpuRenderer's threads draw it.
#include "nodes/render/cpu/SplatSpans.h"

#include "SplatSpansReference.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>
#include <ostream>
#include <utility>

namespace texsplat::render::cpu {
namespace {

using test::CompositeWorkload;
using test::WorkloadCamera;

// How close the SIMD image must be to the scalar one, per channel: the largest difference
// relative to the reference pixel, over the pixels at least kRelativeFloor of the channel's peak,
// and the largest relative to that peak, over all pixels. Fainter pixels are the rims of
// footprints, where the two paths' rounding of the square coordinates (a, b) matters: both
// compute a = a_x·x + a_0 at absolute pixel coordinates, whose two terms nearly cancel, the SIMD
// path with fused multiply-adds, the scalar one without; a difference of 1e-6 in a moves f by
// 1e-4 of itself where it has fallen to 1e-3 of its peak.
constexpr double kRelativeTolerance = 1e-5;
constexpr double kPeakTolerance = 1e-5;
constexpr double kRelativeFloor = 1e-2;

// Rows per band the SIMD path draws at a time, as CpuRenderer's threads would: a band boundary
// must change nothing.
constexpr int kBandRows = 37;

// The largest difference of one kind (see kRelativeTolerance) and where it is.
struct Difference {
    double value = 0.0;
    double simd = 0.0;
    double scalar = 0.0;
    int row = -1;
    int column = -1;
    const char* channel = "";

    // Keeps the worse of this and `other` (NaN counting as the worst).
    void keepWorse(const Difference& other) {
        if (!(other.value <= value)) {
            *this = other;
        }
    }
};

std::ostream& operator<<(std::ostream& out, const Difference& difference) {
    return out << difference.value << " (" << difference.channel << " at row " << difference.row
               << ", column " << difference.column << ": SIMD (" << compositeTarget() << ") "
               << difference.simd << ", scalar " << difference.scalar << ")";
}

struct Differences {
    Difference relative; // to the reference pixel, above kRelativeFloor of the peak
    Difference peak;     // to the channel's peak
};

Differences compare(ColorPlanes& simd, ColorPlanes& scalar) {
    using Plane = float* (ColorPlanes::*)(int);
    const std::array<std::pair<const char*, Plane>, 4> channels{
        {{"red", &ColorPlanes::red},
         {"green", &ColorPlanes::green},
         {"blue", &ColorPlanes::blue},
         {"alpha", &ColorPlanes::alpha}}};
    Differences worst;
    for (const auto& [name, plane] : channels) {
        double peak = 0.0;
        for (int row = 0; row < scalar.height(); ++row) {
            const float* values = (scalar.*plane)(row);
            for (int column = 0; column < scalar.width(); ++column) {
                peak = std::max(peak, std::abs(static_cast<double>(values[column])));
            }
        }
        for (int row = 0; row < scalar.height(); ++row) {
            const float* expected = (scalar.*plane)(row);
            const float* actual = (simd.*plane)(row);
            for (int column = 0; column < scalar.width(); ++column) {
                const double reference = expected[column];
                const double difference = std::abs(actual[column] - reference);
                if (std::abs(reference) >= kRelativeFloor * peak) {
                    worst.relative.keepWorse({difference / std::abs(reference), actual[column],
                                              reference, row, column, name});
                }
                worst.peak.keepWorse(
                    {difference / peak, actual[column], reference, row, column, name});
            }
        }
    }
    return worst;
}

// Composites `workload` with both paths into planes prepared by `prepare` and expects the same
// image within `relativeTolerance` (see kRelativeTolerance); answers the fragments drawn.
std::uint64_t expectMatchesReference(const CompositeWorkload& workload,
                                     const std::function<void(ColorPlanes&)>& prepare = {},
                                     bool withDepth = false,
                                     double relativeTolerance = kRelativeTolerance) {
    const glm::vec4 background(0.05f, 0.1f, 0.15f, 0.2f);
    ColorPlanes simd(workload.width, workload.height, background, withDepth);
    ColorPlanes scalar(workload.width, workload.height, background, withDepth);
    if (prepare) {
        prepare(simd);
        prepare(scalar);
    }
    for (int row = 0; row < workload.height; row += kBandRows) {
        compositeSplats(workload.splats.data(), workload.rows.data(), workload.splats.size(),
                        workload.sampler.get(), workload.stamps(), nullptr, simd, row,
                        std::min(row + kBandRows, workload.height));
    }
    const std::uint64_t fragments =
        test::compositeSplatsScalar(workload.splats.data(), workload.splats.size(),
                                    *workload.sampler, workload.stamps(), scalar, 0,
                                    workload.height);
    const Differences differences = compare(simd, scalar);
    EXPECT_LE(differences.relative.value, relativeTolerance)
        << differences.relative << "; " << workload.splats.size() << " splats";
    EXPECT_LE(differences.peak.value, kPeakTolerance)
        << differences.peak << "; " << workload.splats.size() << " splats";
    EXPECT_GT(fragments, 10u * workload.splats.size()) << "the splats cover hardly any pixel";
    return fragments;
}

TEST(SplatSpans, matchesScalarReferenceOrthographic) {
    // Stamped (FootprintStamps, as CpuRenderer draws them) and with the exact lookup.
    for (const bool stamped : {true, false}) {
        SCOPED_TRACE(stamped ? "stamped" : "exact lookup");
        const CompositeWorkload workload = test::compositeWorkload(
            "blob32", "texture", WorkloadCamera::Orthographic, 128, true, stamped);
        ASSERT_GT(workload.splats.size(), 1000u);
        ASSERT_TRUE(workload.sampler->isRadial);
        ASSERT_EQ(workload.stamps() != nullptr, stamped);
        const std::int32_t flags = stamped ? SplatRaster::kStamped : 0;
        EXPECT_TRUE(std::all_of(workload.splats.begin(), workload.splats.end(),
                                [&](const SplatRaster& splat) { return splat.flags == flags; }));
        expectMatchesReference(workload);
    }
}

TEST(SplatSpans, matchesScalarReferenceForStampedSplatsAcrossTheImagesBorders) {
    // Stamped splats three times as wide (blend error ~1e-4): many reach past the image's
    // edges, where the boxes are clipped and the loop starts inside a stamp's row.
    const CompositeWorkload workload =
        test::compositeWorkload("blob32", "texture", WorkloadCamera::OrthographicClose, 128);
    ASSERT_NE(workload.stamps(), nullptr);
    std::size_t left = 0;
    std::size_t right = 0;
    std::size_t top = 0;
    std::size_t bottom = 0;
    for (const SplatRaster& splat : workload.splats) {
        ASSERT_EQ(splat.flags, SplatRaster::kStamped);
        left += splat.stampColumn < 0 ? 1 : 0;
        right += splat.stampColumn + workload.stamps()->columns > workload.width ? 1 : 0;
        top += splat.stampRow < 0 ? 1 : 0;
        bottom += splat.stampRow + workload.stamps()->rows > workload.height ? 1 : 0;
    }
    // The blob fills the view's left, right and top edges (its lower part is empty).
    EXPECT_GT(std::min({left, right, top}), 50u)
        << left << " " << right << " " << top << " " << bottom;
    expectMatchesReference(workload);
}

TEST(SplatSpans, matchesScalarReferencePerspective) {
    const CompositeWorkload workload =
        test::compositeWorkload("blob32", "texture", WorkloadCamera::Perspective, 128);
    ASSERT_GT(workload.splats.size(), 1000u);
    EXPECT_TRUE(std::all_of(workload.splats.begin(), workload.splats.end(),
                            [](const SplatRaster& splat) {
                                return (splat.flags & SplatRaster::kProjective) != 0;
                            }));
    expectMatchesReference(workload);
}

TEST(SplatSpans, matchesScalarReferenceWithTheEyeInsideTheVolume) {
    const CompositeWorkload workload =
        test::compositeWorkload("blob32", "texture", WorkloadCamera::Inside, 128);
    ASSERT_TRUE(std::any_of(workload.splats.begin(), workload.splats.end(),
                            [](const SplatRaster& splat) {
                                return (splat.flags & SplatRaster::kClipped) != 0;
                            }));
    expectMatchesReference(workload);
}

TEST(SplatSpans, matchesScalarReferenceForTheTabulatedFanFootprint) {
    const CompositeWorkload workload =
        test::compositeWorkload("blob32", "polygon", WorkloadCamera::Perspective, 128);
    ASSERT_FALSE(workload.sampler->isRadial);
    expectMatchesReference(workload);
}

TEST(SplatSpans, matchesScalarReferenceForThickAndPurelyEmissiveMedia) {
    // The blob's splats are optically thin (the φ series); scaled up, most take Expm1, and every
    // third emits without absorbing (C·f). Thick splats show their rims down to a hundredth of
    // the footprint's peak, where the rounding of (a, b) moves f by up to 1e-4 of itself (see
    // kRelativeTolerance): measured 2e-5, allowed 5e-5.
    CompositeWorkload workload =
        test::compositeWorkload("blob32", "texture", WorkloadCamera::Perspective, 128);
    std::size_t thick = 0;
    for (std::size_t i = 0; i < workload.splats.size(); ++i) {
        SplatRaster& splat = workload.splats[i];
        splat.extinction = i % 3 == 0 ? 0.0f : 400.0f * splat.extinction;
        thick += splat.extinction * splat.lengthScale * workload.sampler->peak > 0.5f ? 1 : 0;
    }
    ASSERT_GT(thick, workload.splats.size() / 2);
    expectMatchesReference(workload, {}, false, 5e-5);
}

TEST(SplatSpans, matchesScalarReferenceForEveryOpticalDepthAndBoxWidth) {
    // The loop computes α and the colour weight by φ's short series (largest optical depth up to
    // 0.1), its long series (up to ½) or Expm1, and draws boxes up to 8 pixels wide with 8 lanes,
    // wider ones with 16 (AVX-512). Extinctions spread the blob's splats over the three ranges,
    // and two image sizes give both widths.
    for (const int size : {64, 160}) {
        SCOPED_TRACE(size);
        CompositeWorkload workload =
            test::compositeWorkload("blob32", "texture", WorkloadCamera::Perspective, size);
        std::array<std::size_t, 3> depths{};
        std::array<std::size_t, 2> widths{};
        for (std::size_t i = 0; i < workload.splats.size(); ++i) {
            SplatRaster& splat = workload.splats[i];
            const float largest = 1e-3f * std::pow(1e4f, static_cast<float>(i % 97) / 96.0f);
            splat.extinction = largest / (splat.lengthScale * workload.sampler->peak);
            ++depths[largest <= 0.1f ? 0 : largest <= 0.5f ? 1 : 2];
            ++widths[splat.columnEnd - splat.columnBegin <= 8 ? 0 : 1];
        }
        for (const std::size_t count : depths) {
            EXPECT_GT(count, workload.splats.size() / 10);
        }
        EXPECT_GT(widths[size == 64 ? 0 : 1], workload.splats.size() / 2)
            << widths[0] << " boxes up to 8 pixels wide, " << widths[1] << " wider";
        expectMatchesReference(workload, {}, false, 5e-5);
    }
}

TEST(SplatSpans, matchesScalarReferenceBehindADepthPlane) {
    // A depth plane slanting through the volume hides part of each splat, as a mesh would; the
    // orthographic splats are stamped.
    for (const WorkloadCamera camera :
         {WorkloadCamera::Perspective, WorkloadCamera::Orthographic}) {
        SCOPED_TRACE(camera == WorkloadCamera::Perspective ? "perspective" : "orthographic");
        const CompositeWorkload workload =
            test::compositeWorkload("blob32", "texture", camera, 128);
        // The window depths of the splats' centres, which the plane slants across.
        float nearest = 1.0f;
        float farthest = 0.0f;
        for (const SplatRaster& splat : workload.splats) {
            const float x = 0.5f * static_cast<float>(splat.columnBegin + splat.columnEnd);
            const float y = 0.5f * static_cast<float>(splat.rowBegin + splat.rowEnd);
            const float window =
                0.5f * (splat.depth[0] * x + splat.depth[1] * y + splat.depth[2]) + 0.5f;
            nearest = std::min(nearest, window);
            farthest = std::max(farthest, window);
        }
        ASSERT_LT(nearest, farthest);
        const auto slantedDepth = [&](ColorPlanes& planes) {
            for (int row = 0; row < planes.height(); ++row) {
                float* depth = planes.depth(row);
                for (int column = 0; column < planes.width(); ++column) {
                    const float across = static_cast<float>(column + row) /
                                         static_cast<float>(planes.width() + planes.height());
                    depth[column] = nearest + (farthest - nearest) * (0.3f + 0.4f * across);
                }
            }
        };
        const std::uint64_t hidden = expectMatchesReference(workload, slantedDepth, true);
        const std::uint64_t all = expectMatchesReference(workload);
        EXPECT_LT(hidden, all);
        EXPECT_GT(hidden, all / 10);
    }
}

TEST(SplatSpans, matchesScalarReferenceOnEveryInstructionSet) {
    // The loop is compiled for every x86 target and picked at run time; the register lookup of
    // the cubic pieces takes one permute on 16 lanes, two and a select on 8, four on 4. Each
    // target this CPU runs must draw the reference's image.
    // The orthographic splats are stamped.
    const CompositeWorkload perspective =
        test::compositeWorkload("blob32", "texture", WorkloadCamera::Perspective, 128);
    const CompositeWorkload orthographic =
        test::compositeWorkload("blob32", "texture", WorkloadCamera::Orthographic, 128);
    ASSERT_TRUE(perspective.sampler->hasPieces);
    ASSERT_NE(orthographic.stamps(), nullptr);
    const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        SCOPED_TRACE(compositeTarget());
        EXPECT_EQ(std::string(compositeTarget()), hwy::TargetName(target));
        expectMatchesReference(perspective);
        expectMatchesReference(orthographic);
    }
    hwy::SetSupportedTargetsForTest(0);
    EXPECT_GT(targets.size(), 1u) << "only " << compositeTarget() << " was tried";
}

TEST(SplatSetup, theDiscsPixelBoxHoldsEveryPixelTheFootprintReaches) {
    // A radial footprint's pixel box bounds the ellipse its disc projects to (the dual conic in
    // perspective), much tighter than the square's box of an oblique view; no pixel whose
    // centre lies within the reach may fall outside it, and the image is the square boxes' one.
    for (const WorkloadCamera camera :
         {WorkloadCamera::Orthographic, WorkloadCamera::Perspective, WorkloadCamera::Inside}) {
        SCOPED_TRACE(static_cast<int>(camera));
        // Unstamped: the stamps' boxes are their own (SplatSetupStamps tests).
        const CompositeWorkload square =
            test::compositeWorkload("blob32", "texture", camera, 128, false, false);
        const CompositeWorkload disc =
            test::compositeWorkload("blob32", "texture", camera, 128, true, false);
        ASSERT_LE(disc.splats.size(), square.splats.size());
        std::uint64_t squarePixels = 0;
        std::uint64_t discPixels = 0;
        std::uint64_t lost = 0;
        std::size_t next = 0; // the disc's raster of the same splat (or none: its box is empty)
        for (std::size_t i = 0; i < square.splats.size(); ++i) {
            const SplatRaster& wide = square.splats[i];
            while (next < disc.splats.size() && disc.sources[next] < square.sources[i]) {
                ++next;
            }
            const SplatRaster tight = next < disc.splats.size() &&
                                              disc.sources[next] == square.sources[i]
                                          ? disc.splats[next]
                                          : SplatRaster{};
            squarePixels += std::uint64_t(wide.rowEnd - wide.rowBegin) *
                            std::uint64_t(wide.columnEnd - wide.columnBegin);
            discPixels += std::uint64_t(tight.rowEnd - tight.rowBegin) *
                          std::uint64_t(tight.columnEnd - tight.columnBegin);
            const float* q = wide.square;
            for (int row = wide.rowBegin; row < wide.rowEnd; ++row) {
                for (int column = wide.columnBegin; column < wide.columnEnd; ++column) {
                    const auto x = static_cast<float>(column);
                    const auto y = static_cast<float>(row);
                    const float w = q[6] * x + q[7] * y + q[8];
                    const float a = (q[0] * x + q[1] * y + q[2]) / w;
                    const float b = (q[3] * x + q[4] * y + q[5]) / w;
                    const bool reached = w > 0.0f && a * a + b * b <= square.sampler->reach;
                    const bool inBox = row >= tight.rowBegin && row < tight.rowEnd &&
                                       column >= tight.columnBegin && column < tight.columnEnd;
                    lost += reached && !inBox ? 1 : 0;
                }
            }
        }
        EXPECT_EQ(lost, 0u);
        if (camera != WorkloadCamera::Inside) {
            EXPECT_LT(discPixels, squarePixels * 7 / 10) << "the disc's boxes are tighter";
        }
        const glm::vec4 background(0.0f);
        ColorPlanes fromSquare(square.width, square.height, background, false);
        ColorPlanes fromDisc(disc.width, disc.height, background, false);
        compositeSplats(square.splats.data(), square.rows.data(), square.splats.size(),
                        square.sampler.get(), nullptr, nullptr, fromSquare, 0, square.height);
        compositeSplats(disc.splats.data(), disc.rows.data(), disc.splats.size(),
                        disc.sampler.get(), nullptr, nullptr, fromDisc, 0, disc.height);
        for (int row = 0; row < square.height; ++row) {
            ASSERT_EQ(std::memcmp(fromSquare.alpha(row), fromDisc.alpha(row),
                                  sizeof(float) * static_cast<std::size_t>(square.width)),
                      0)
                << "row " << row;
        }
    }
}

TEST(FootprintSampler, cubicPiecesFollowThePapersKernelAsCloselyAsTheProfile) {
    // The SIMD loop looks the paper's radial footprint up in 16 cubics (in registers) instead
    // of the 4096-sample profile (gathered): they must follow the kernel that closely. A
    // truncated Gaussian falls to 0 like a square root at its edge, which cubics follow only to
    // 1e-3 of its peak: it keeps the profile.
    const CompositeWorkload paper =
        test::compositeWorkload("blob16", "texture", WorkloadCamera::Orthographic, 64);
    ASSERT_TRUE(paper.sampler->isRadial);
    EXPECT_TRUE(paper.sampler->hasPieces);
    EXPECT_LE(paper.sampler->pieceError, 1e-5 * paper.sampler->peak);
    const CompositeWorkload gaussian =
        test::compositeWorkload("blob16", "texture-gaussian", WorkloadCamera::Orthographic, 64);
    ASSERT_TRUE(gaussian.sampler->isRadial);
    EXPECT_FALSE(gaussian.sampler->hasPieces) << gaussian.sampler->pieceError;
}

TEST(SplatSpans, matchesScalarReferenceForTheTruncatedGaussiansProfile) {
    const CompositeWorkload workload =
        test::compositeWorkload("blob32", "texture-gaussian", WorkloadCamera::Perspective, 128);
    ASSERT_TRUE(workload.sampler->isRadial);
    ASSERT_FALSE(workload.sampler->hasPieces);
    expectMatchesReference(workload);
}

} // namespace
} // namespace texsplat::render::cpu
