// render::cpu::FootprintStamps, the footprint of an orthographic batch's unit-size splats
// tabulated per sub-pixel phase: where SplatSetup makes them, how close a splat's stamp is to
// the footprint of its own centre (the stated error), where a centre is placed, and how far the
// image moves from the exact lookup's.
#include "nodes/render/cpu/FootprintStamps.h"

#include "SplatSpansReference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <string>
#include <utility>

namespace texsplat::render::cpu {
namespace {

using test::CompositeWorkload;
using test::WorkloadCamera;

TEST(FootprintStamps, areMadeForOrthographicViewsOfThePapersKernelOnly) {
    EXPECT_NE(test::compositeWorkload("blob32", "texture", WorkloadCamera::Orthographic, 128)
                  .stamps(),
              nullptr);
    // A homography per splat; the truncated Gaussian's edge; the polygonal fan's texture.
    EXPECT_EQ(test::compositeWorkload("blob32", "texture", WorkloadCamera::Perspective, 128)
                  .stamps(),
              nullptr);
    EXPECT_EQ(
        test::compositeWorkload("blob32", "texture-gaussian", WorkloadCamera::Orthographic, 128)
            .stamps(),
        nullptr);
    EXPECT_EQ(test::compositeWorkload("blob32", "polygon", WorkloadCamera::Orthographic, 128)
                  .stamps(),
              nullptr);
    // Splats a few pixels wide bend more within a phase: more phases, each stamp within
    // kTolerance of the peak; splats about a pixel wide bend too much even at the most phases
    // the table holds and keep the exact lookup; splats 70 pixels wide would make a table of
    // 256 × 70² floats and gain nothing.
    for (const int size : {8, 12}) {
        EXPECT_EQ(test::compositeWorkload("blob32", "texture", WorkloadCamera::Orthographic, size)
                      .stamps(),
                  nullptr)
            << size;
    }
    for (const int size : {16, 24, 32}) {
        const CompositeWorkload narrow =
            test::compositeWorkload("blob32", "texture", WorkloadCamera::Orthographic, size);
        ASSERT_NE(narrow.stamps(), nullptr) << size;
        EXPECT_GT(narrow.stamps()->phases(), FootprintStamps::kPhases) << size;
        EXPECT_LE(narrow.stamps()->error, FootprintStamps::kTolerance * narrow.stamps()->peak)
            << size;
    }
    const CompositeWorkload wide =
        test::compositeWorkload("blob32", "texture", WorkloadCamera::Orthographic, 1024);
    EXPECT_EQ(wide.stamps(), nullptr);
    EXPECT_FALSE(wide.splats.empty());
}

// Every `step`-th splat of `workload`: its stamp at every pixel of a margin of 2 around its
// box against the exact footprint of its own centre there (0 outside the box). Returns the
// largest difference.
double largestStampDifference(const CompositeWorkload& workload, std::size_t step) {
    const FootprintStamps& stamps = *workload.stamps();
    double largest = 0.0;
    for (std::size_t i = 0; i < workload.splats.size(); i += step) {
        const SplatRaster& splat = workload.splats[i];
        EXPECT_EQ(splat.flags, SplatRaster::kStamped);
        const float* q = splat.square;
        for (int row = splat.rowBegin - 2; row < splat.rowEnd + 2; ++row) {
            for (int column = splat.columnBegin - 2; column < splat.columnEnd + 2; ++column) {
                const auto x = static_cast<float>(column);
                const auto y = static_cast<float>(row);
                const float exact =
                    test::sampleFootprint(*workload.sampler, q[0] * x + (q[1] * y + q[2]),
                                          q[3] * x + (q[4] * y + q[5])) *
                    splat.lengthScale;
                const bool inBox = row >= splat.rowBegin && row < splat.rowEnd &&
                                   column >= splat.columnBegin && column < splat.columnEnd;
                const float stamp = inBox ? stamps.at(splat.stampPhase, column - splat.stampColumn,
                                                      row - splat.stampRow)
                                          : 0.0f;
                largest = std::max(largest, static_cast<double>(std::abs(stamp - exact)));
            }
        }
    }
    return largest;
}

TEST(FootprintStamps, standWithinTheStatedErrorForTheFootprintOfEveryCentre) {
    // Splats about 4.5 and 9 pixels in radius (blob32 in 128², blob64 in 512², the size of
    // Marschner–Lobb 128³'s in 512²: 4.5), and about 1.5 (blob32 in 48²), whose footprint bends
    // more within a phase: the phases double until the error is within the tolerance.
    for (const auto& [dataset, size] : std::array<std::pair<const char*, int>, 3>{
             {{"blob32", 128}, {"blob64", 512}, {"blob32", 48}}}) {
        SCOPED_TRACE(std::string(dataset) + " in " + std::to_string(size));
        const CompositeWorkload workload =
            test::compositeWorkload(dataset, "texture", WorkloadCamera::Orthographic, size);
        ASSERT_NE(workload.stamps(), nullptr);
        const FootprintStamps& stamps = *workload.stamps();
        EXPECT_GT(stamps.error, 0.0f);
        EXPECT_LE(stamps.error, FootprintStamps::kTolerance * stamps.peak);
        // The error is measured at the corners and edges of each phase's cell of centres;
        // the splats' own centres lie inside, within it (and the rounding of (a, b)).
        const double largest = largestStampDifference(workload, 5);
        EXPECT_LE(largest, 1.02 * stamps.error + 1e-6 * stamps.peak);
        EXPECT_GT(largest, 0.5 * stamps.error) << "the splats' centres should test the stamps";
        std::cout << "[ stamps   ] " << dataset << " in " << size << "²: " << stamps.phases()
                  << "² phases, error " << stamps.error / stamps.peak
                  << " of the peak, largest at the splats " << largest / stamps.peak << "\n";
    }
}

TEST(FootprintStamps, aPlaceIsTheNearestPhase) {
    const CompositeWorkload workload =
        test::compositeWorkload("blob32", "texture", WorkloadCamera::Orthographic, 128);
    ASSERT_NE(workload.stamps(), nullptr);
    const FootprintStamps& stamps = *workload.stamps();
    ASSERT_EQ(stamps.phases(), FootprintStamps::kPhases);
    FootprintStamps::Place place{};
    // Pixel 10's centre is at 10.5: a centre 0.03 of a pixel past it rounds to phase 0, one
    // 0.04 past to phase 1 (1/16 = 0.0625), one 0.97 past to the next pixel's phase 0.
    ASSERT_TRUE(stamps.place(10.53f, 20.5f, place));
    EXPECT_EQ(place.phase, stamps.phaseIndex(0, 0));
    EXPECT_EQ(place.column, 10 + stamps.columnOffset);
    EXPECT_EQ(place.row, 20 + stamps.rowOffset);
    ASSERT_TRUE(stamps.place(10.54f, 20.5f + 15.0f / 16.0f, place));
    EXPECT_EQ(place.phase, stamps.phaseIndex(1, 15));
    ASSERT_TRUE(stamps.place(-0.5f + 0.98f, 0.5f - 1.0f / 16.0f, place));
    EXPECT_EQ(place.phase, stamps.phaseIndex(0, 15));
    EXPECT_EQ(place.column, 0 + stamps.columnOffset);
    EXPECT_EQ(place.row, -1 + stamps.rowOffset);
    // Too far out for the int arithmetic: refused, the place unchanged.
    EXPECT_FALSE(stamps.place(1e9, 0.0, place));
    EXPECT_FALSE(stamps.place(0.0, -std::numeric_limits<double>::infinity(), place));
    EXPECT_FALSE(stamps.place(std::numeric_limits<double>::quiet_NaN(), 0.0, place));
    EXPECT_EQ(place.row, -1 + stamps.rowOffset);
}

TEST(FootprintStamps, theImageIsTheExactLookupsWithinTheStampsError) {
    // The whole blob64 frame in 512², stamped and with the exact lookup, both through the SIMD
    // loop: a pixel's difference is at most the sum over its splats of what the footprint's
    // error changes, (|C| + τ·dst)·error each; in practice the errors of neighbouring splats
    // do not add up, and the image moves by about the stamps' relative error.
    const CompositeWorkload stamped =
        test::compositeWorkload("blob64", "texture", WorkloadCamera::Orthographic, 512);
    const CompositeWorkload exact = test::compositeWorkload(
        "blob64", "texture", WorkloadCamera::Orthographic, 512, true, false);
    ASSERT_NE(stamped.stamps(), nullptr);
    const glm::vec4 background(0.0f);
    ColorPlanes fromStamps(stamped.width, stamped.height, background, false);
    ColorPlanes fromExact(exact.width, exact.height, background, false);
    compositeSplats(stamped.splats.data(), stamped.rows.data(), stamped.splats.size(),
                    stamped.sampler.get(), stamped.stamps(), nullptr, fromStamps, 0,
                    stamped.height);
    compositeSplats(exact.splats.data(), exact.rows.data(), exact.splats.size(),
                    exact.sampler.get(), nullptr, nullptr, fromExact, 0, exact.height);
    double peak = 0.0;
    double largest = 0.0;
    double squares = 0.0;
    for (int row = 0; row < stamped.height; ++row) {
        for (int column = 0; column < stamped.width; ++column) {
            const double a = fromExact.alpha(row)[column];
            const double difference = std::abs(fromStamps.alpha(row)[column] - a);
            peak = std::max(peak, a);
            largest = std::max(largest, difference);
            squares += difference * difference;
        }
    }
    ASSERT_GT(peak, 0.1);
    const double relativeError = stamped.stamps()->error / stamped.stamps()->peak;
    const double rms = std::sqrt(squares / (stamped.width * stamped.height));
    std::cout << "[ stamps   ] blob64 in 512², alpha: largest difference " << largest / peak
              << " of the peak, RMS " << rms / peak << " (stamps' error " << relativeError
              << ")\n";
    EXPECT_LE(largest, 4.0 * relativeError * peak);
    EXPECT_LE(rms, relativeError * peak);
}

} // namespace
} // namespace texsplat::render::cpu
