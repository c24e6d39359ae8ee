#include "nodes/TransferFunction.h"
#include "nodes/detail/TransferTable.h"

#include "SceneNodesTestSupport.h"
#include "nodes/elements/TransferFunctionElement.h"
#include "nodes/image/detail/Viridis.h"
#include "nodes/volume/DenseGrid.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <vector>
#include <limits>

namespace texsplat::nodes {
namespace {

using test::errorOf;

constexpr float kTolerance = 1e-6f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = kTolerance) {
    EXPECT_NEAR(actual.r, expected.r, tolerance);
    EXPECT_NEAR(actual.g, expected.g, tolerance);
    EXPECT_NEAR(actual.b, expected.b, tolerance);
}

TEST(TransferFunction, defaultIsAGrayRampWithALinearOpacityRamp) {
    const auto tf = TransferFunction::create();
    const Classification half = tf->classify(0.5f);
    EXPECT_FLOAT_EQ(half.extinction, 0.5f);
    expectNear(half.color, glm::vec3(0.25f)); // S = 0.5, C = S * tau
    const Classification top = tf->classify(1.0f);
    EXPECT_FLOAT_EQ(top.extinction, 1.0f);
    expectNear(top.color, glm::vec3(1.0f));
}

TEST(TransferFunction, presetsGiveTheirColours) {
    const auto tf = TransferFunction::create();
    tf->opacities.setValue({1.0f, 1.0f}); // tau = 1: C equals the colour S
    tf->preset.setValue(ColorPreset::Hot);
    expectNear(tf->classify(0.0f).color, glm::vec3(0.0f));
    expectNear(tf->classify(0.375f).color, glm::vec3(1.0f, 0.0f, 0.0f));
    expectNear(tf->classify(0.75f).color, glm::vec3(1.0f, 1.0f, 0.0f));
    expectNear(tf->classify(1.0f).color, glm::vec3(1.0f));
    tf->preset.setValue(ColorPreset::CoolWarm);
    expectNear(tf->classify(0.0f).color, glm::vec3(0.230f, 0.299f, 0.754f));
    expectNear(tf->classify(0.5f).color, glm::vec3(0.865f));
    expectNear(tf->classify(1.0f).color, glm::vec3(0.706f, 0.016f, 0.150f));
    tf->preset.setValue(ColorPreset::Viridis);
    for (const float t : {0.0f, 0.1f, 0.5f, 0.77f, 1.0f}) {
        expectNear(tf->classify(t).color, image::detail::viridis(t), 1e-5f);
    }
}

TEST(TransferFunction, brownsIsANoisyBrownRamp) {
    const auto tf = TransferFunction::create();
    tf->opacities.setValue({1.0f, 1.0f});
    tf->preset.setValue(ColorPreset::Browns);
    int brightnessReversals = 0;
    float previousBrightness = -1.0f;
    for (int i = 0; i < 64; ++i) {
        const glm::vec3 color = tf->classify(float(i) / 63.0f).color;
        EXPECT_GT(color.r, color.g) << i; // brown: red over green over blue
        EXPECT_GT(color.g, color.b) << i;
        EXPECT_LE(color.r, 1.0f) << i;
        const float brightness = color.r + color.g + color.b;
        brightnessReversals += brightness < previousBrightness ? 1 : 0;
        previousBrightness = brightness;
    }
    EXPECT_GT(brightnessReversals, 5); // noisy, not a smooth ramp
    // Dark at the low end, light at the high end.
    EXPECT_LT(tf->classify(0.0f).color.r, 0.4f);
    EXPECT_GT(tf->classify(1.0f).color.r, 0.6f);
    // The same map every time (a fixed hash, not a random generator).
    const auto other = TransferFunction::create();
    other->opacities.setValue({1.0f, 1.0f});
    other->preset.setValue(ColorPreset::Browns);
    EXPECT_EQ(other->classify(0.3f).color, tf->classify(0.3f).color);
}

TEST(TransferFunction, controlPointsOverrideThePreset) {
    const auto tf = TransferFunction::create();
    tf->preset.setValue(ColorPreset::Hot);
    tf->colorValues.setValue({0.0f, 0.5f, 1.0f});
    tf->colors.setValue({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    tf->opacityValues.setValue({0.0f, 1.0f});
    tf->opacities.setValue({2.0f, 2.0f});
    const Classification quarter = tf->classify(0.25f);
    EXPECT_FLOAT_EQ(quarter.extinction, 2.0f);
    expectNear(quarter.color, glm::vec3(1.0f, 1.0f, 0.0f)); // S = (0.5, 0.5, 0), C = 2 S
}

TEST(TransferFunction, valuesOutsideTheRangeClamp) {
    const auto tf = TransferFunction::create();
    tf->range = glm::vec2(10.0f, 20.0f);
    tf->opacities.setValue({0.5f, 3.0f});
    EXPECT_FLOAT_EQ(tf->classify(15.0f).extinction, 1.75f);
    EXPECT_FLOAT_EQ(tf->classify(5.0f).extinction, 0.5f);
    EXPECT_FLOAT_EQ(tf->classify(25.0f).extinction, 3.0f);
    const float infinity = std::numeric_limits<float>::infinity();
    EXPECT_FLOAT_EQ(tf->classify(infinity).extinction, 3.0f);
    EXPECT_FLOAT_EQ(tf->classify(-infinity).extinction, 0.5f);
    EXPECT_FLOAT_EQ(tf->classify(std::numeric_limits<float>::max()).extinction, 3.0f);
    EXPECT_FLOAT_EQ(tf->classify(std::numeric_limits<float>::lowest()).extinction, 0.5f);
}

TEST(TransferFunction, nanIsFullyTransparent) {
    const auto tf = TransferFunction::create();
    tf->opacities.setValue({1.0f, 1.0f});
    tf->emission = 1.0f;
    const Classification nan = tf->classify(std::numeric_limits<float>::quiet_NaN());
    EXPECT_EQ(nan.extinction, 0.0f);
    EXPECT_EQ(nan.color, glm::vec3(0.0f));
}

TEST(TransferFunction, emissionMakesTransparentVoxelsGlow) {
    // The paper's Figure 2 experiment: glowing, fully transparent voxels.
    const auto tf = TransferFunction::create();
    tf->opacities.setValue({0.0f, 0.0f});
    tf->emission = 1.0f;
    const Classification result = tf->classify(0.5f);
    EXPECT_EQ(result.extinction, 0.0f);
    expectNear(result.color, glm::vec3(0.5f)); // C = S
    tf->opacities.setValue({2.0f, 2.0f});
    expectNear(tf->classify(0.5f).color, glm::vec3(1.5f)); // C = S (tau + emission)
}

TEST(TransferFunction, repeatedPositionsMakeAStep) {
    const auto tf = TransferFunction::create();
    tf->opacityValues.setValue({0.0f, 0.5f, 0.5f, 1.0f});
    tf->opacities.setValue({0.0f, 0.0f, 4.0f, 4.0f});
    EXPECT_EQ(tf->classify(0.49f).extinction, 0.0f);
    EXPECT_EQ(tf->classify(0.5f).extinction, 4.0f);
    EXPECT_EQ(tf->classify(0.51f).extinction, 4.0f);
}

TEST(TransferFunction, lookupsInterpolateInTheBinarySearchesSegment) {
    // A lookup is the interpolation in the segment a binary search finds, bit for bit, at and
    // next to every control point and step, on maps of 2 to 300 points with repeated positions.
    std::mt19937 random(20261126);
    for (const std::size_t points : {2, 3, 7, 64, 256, 300}) {
        std::uniform_real_distribution<float> position(-3.0f, 5.0f);
        std::vector<float> x(points);
        for (float& value : x) {
            value = position(random);
        }
        std::sort(x.begin(), x.end());
        for (std::size_t i = 1; i < points; i += 5) {
            x[i] = x[i - 1]; // steps
        }
        std::vector<float> y(points);
        for (float& value : y) {
            value = position(random);
        }
        const nodes::detail::PiecewiseLinear<float> map{x, y};
        const auto searched = [&](float t) {
            if (!(t > x.front())) {
                return y.front();
            }
            if (t >= x.back()) {
                return y.back();
            }
            const auto i = static_cast<std::size_t>(
                std::distance(x.begin(), std::upper_bound(x.begin(), x.end(), t)));
            const float weight = (t - x[i - 1]) / (x[i] - x[i - 1]);
            return y[i - 1] + weight * (y[i] - y[i - 1]);
        };
        std::vector<float> probes;
        for (const float point : x) {
            probes.push_back(point);
            probes.push_back(std::nextafter(point, -INFINITY));
            probes.push_back(std::nextafter(point, INFINITY));
        }
        for (int i = 0; i < 10000; ++i) {
            probes.push_back(position(random));
        }
        for (const float t : probes) {
            ASSERT_EQ(map(t), searched(t)) << points << " points, t = " << t;
        }
    }
}

TEST(TransferFunction, aSingleControlPointIsConstant) {
    const auto tf = TransferFunction::create();
    tf->opacityValues.setValue({0.3f});
    tf->opacities.setValue({0.7f});
    EXPECT_FLOAT_EQ(tf->classify(0.0f).extinction, 0.7f);
    EXPECT_FLOAT_EQ(tf->classify(1.0f).extinction, 0.7f);
}

TEST(TransferFunction, aFieldChangeTakesEffect) {
    const auto tf = TransferFunction::create();
    EXPECT_FLOAT_EQ(tf->classify(1.0f).extinction, 1.0f);
    tf->opacities.set1Value(1, 5.0f);
    EXPECT_FLOAT_EQ(tf->classify(1.0f).extinction, 5.0f);
    tf->range = glm::vec2(0.0f, 2.0f);
    EXPECT_FLOAT_EQ(tf->classify(1.0f).extinction, 2.5f);
}

TEST(TransferFunction, reportsInvalidFieldsByName) {
    const auto tf = TransferFunction::create();
    tf->setName("tf");
    const auto message = [&] { return errorOf<DataError>([&] { tf->classify(0.5f); }); };

    tf->colorValues.setValue({0.0f, 0.5f, 1.0f});
    tf->colors.setValue({{1, 0, 0}, {0, 1, 0}});
    EXPECT_EQ(message(), "TransferFunction 'tf': colorValues has 3 values but colors has 2");
    tf->colorValues.setValue({0.0f, 0.5f});
    tf->colors.setValue({{1, 0, 0}, {0, -1, 0}});
    EXPECT_EQ(message(),
              "TransferFunction 'tf': colors[1] must be finite and not negative, got 0 -1 0");
    tf->colorValues.setValue({0.5f, 0.25f});
    tf->colors.setValue({{1, 0, 0}, {0, 1, 0}});
    EXPECT_EQ(message(), "TransferFunction 'tf': colorValues must not decrease, but "
                         "colorValues[1] = 0.25 follows 0.5");
    tf->colorValues.setValue({0.0f, std::numeric_limits<float>::quiet_NaN()});
    EXPECT_EQ(message(), "TransferFunction 'tf': colorValues[1] must be finite, got nan");
    tf->colorValues.setValue({});
    tf->colors.setValue({});

    tf->opacities.setValue({0.0f, -1.0f});
    EXPECT_EQ(message(), "TransferFunction 'tf': opacities[1] must be finite and not negative "
                         "(opacity per unit length), got -1");
    tf->opacities.setValue({0.0f});
    EXPECT_EQ(message(), "TransferFunction 'tf': opacityValues has 2 values but opacities has 1");
    tf->opacityValues.setValue({});
    tf->opacities.setValue({});
    EXPECT_EQ(message(), "TransferFunction 'tf': opacityValues and opacities are empty; give at "
                         "least one control point");
    tf->opacityValues.setValue({0.0f});
    tf->opacities.setValue({1.0f});

    tf->range = glm::vec2(1.0f, 1.0f);
    EXPECT_EQ(message(),
              "TransferFunction 'tf': range must be finite with range[0] < range[1], got 1 1");
    tf->range = glm::vec2(0.0f, 1.0f);
    tf->emission = -0.5f;
    EXPECT_EQ(message(),
              "TransferFunction 'tf': emission must be finite and not negative, got -0.5");
    EXPECT_EQ(errorOf<DataError>([&] { tf->validate(); }), message());
    tf->emission = 0.0f;
    EXPECT_NO_THROW(tf->validate());
}

TEST(TransferFunction, classifiesAGridIntoTheOctreeInput) {
    using volume::DenseScalarGrid;
    using volume::GridGeometry;
    DenseScalarGrid grid(GridGeometry({3, 2, 1}, {10.0, 20.0, 30.0}, {0.5, 1.0, 2.0}));
    grid.setValue({0, 0, 0}, 0.0f); // classifies to nothing: stays empty
    grid.setValue({1, 0, 0}, 0.5f);
    grid.setValue({2, 0, 0}, std::numeric_limits<float>::quiet_NaN()); // an empty voxel
    grid.setValue({0, 1, 0}, 1.0f);
    grid.setValue({1, 1, 0}, 7.0f); // clamps to 1
    grid.setValue({2, 1, 0}, 0.25f);
    const auto tf = TransferFunction::create();
    tf->range = glm::vec2(0.0f, 1.0f); // written: kept, not fitted to the data (rangeMode AUTO)
    const std::shared_ptr<octree::ClassifiedGrid> classified = tf->classify(grid);
    EXPECT_EQ(classified->dims(), glm::u64vec3(3, 2, 1));
    EXPECT_EQ(classified->origin(), glm::dvec3(10.0, 20.0, 30.0));
    EXPECT_EQ(classified->spacing(), glm::dvec3(0.5, 1.0, 2.0));
    EXPECT_TRUE(classified->isEmptyVoxel(glm::u64vec3(0, 0, 0)));
    EXPECT_TRUE(classified->isEmptyVoxel(glm::u64vec3(2, 0, 0)));
    EXPECT_EQ(classified->voxel(glm::u64vec3(1, 0, 0)),
              glm::vec4(0.25f, 0.25f, 0.25f, 0.5f));
    EXPECT_EQ(classified->voxel(glm::u64vec3(0, 1, 0)), glm::vec4(1.0f));
    EXPECT_EQ(classified->voxel(glm::u64vec3(1, 1, 0)), glm::vec4(1.0f));
    const Classification quarter = tf->classify(0.25f);
    EXPECT_EQ(classified->voxel(glm::u64vec3(2, 1, 0)),
              glm::vec4(quarter.color, quarter.extinction));
}

TEST(TransferFunction, classifyingAGridGivesEachVoxelItsValuesClassificationForAnyThreadCount) {
    // Blocks are read and classified in parallel batches (more than one batch here, and blocks
    // the box clips): every voxel must be what classifyLevel(value) gives it, for 1, 2 and 7
    // threads.
    using volume::DenseScalarGrid;
    using volume::GridGeometry;
    DenseScalarGrid grid(GridGeometry({131, 97, 90}));
    for (std::int64_t z = 0; z < 90; ++z) {
        for (std::int64_t y = 0; y < 97; ++y) {
            for (std::int64_t x = 0; x < 131; ++x) {
                grid.setValue({x, y, z}, std::sin(0.05f * float(x * y)) * std::cos(0.1f * float(z)));
            }
        }
    }
    const auto tf = TransferFunction::create();
    tf->preset.setValue(ColorPreset::Viridis);
    tf->opacityValues.setValue({0.0f, 0.5f, 0.5f, 1.0f});
    tf->opacities.setValue({0.0f, 0.0f, 3.0f, 4.0f});
    const DataScale scale = tf->dataScale(grid);
    for (const int threads : {1, 2, 7}) {
        SCOPED_TRACE(threads);
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                        static_cast<std::size_t>(threads));
        const std::shared_ptr<octree::ClassifiedGrid> classified = tf->classify(grid);
        std::size_t wrong = 0;
        std::uint64_t drawn = 0;
        grid.forEachActive([&](const glm::i64vec3& index, float value) {
            const Classification expected = tf->classifyLevel(value, scale);
            wrong += classified->voxel(glm::u64vec3(index)) !=
                             glm::vec4(expected.color, expected.extinction)
                         ? 1
                         : 0;
            drawn += expected.extinction != 0.0f || expected.color != glm::vec3(0.0f) ? 1 : 0;
        });
        EXPECT_EQ(wrong, 0u);
        EXPECT_EQ(classified->nonEmptyVoxelCount(), drawn);
        EXPECT_GT(drawn, 100000u);
    }
}

TEST(TransferFunction, aVoxelIsItsValuesClassificationWithinHalfALevel) {
    // Colour and opacity change along t at most by their control points' steepest slope, so the
    // level a voxel holds (1/65536 of the range away at most) moves its classification by that
    // slope over half a level at most; values on a level are classified exactly.
    const auto tf = TransferFunction::create();
    tf->colorValues.setValue({0.0f, 0.3f, 1.0f});
    tf->colors.setValue({glm::vec3(0.0f), glm::vec3(1.0f, 0.2f, 0.5f), glm::vec3(0.1f)});
    tf->opacityValues.setValue({0.0f, 0.6f, 1.0f});
    tf->opacities.setValue({0.5f, 40.0f, 2.0f});
    const DataScale scale{glm::vec2(-3.0f, 5.0f), 1.0f};
    // d(C, τ)/dt at most: |τ'| = 39.5/0.6 below t = 0.6 and 38/0.4 above; C = S·τ with
    // |S'| <= 1/0.3 (and S <= 1, τ <= 40), so |C'| <= |τ'| + 40/0.3.
    const double slopeT = std::max(39.5 / 0.6, 38.0 / 0.4);
    const double slopeC = slopeT + 40.0 / 0.3;
    const double halfLevel = 0.5 / (TransferFunction::kLevels - 1);
    double largest = 0.0;
    for (int i = 0; i <= 200000; ++i) {
        const float value = -3.5f + 9.0f * static_cast<float>(i) / 200000.0f;
        const Classification exact = tf->classify(value, scale);
        const Classification level = tf->classifyLevel(value, scale);
        EXPECT_LE(std::abs(level.extinction - exact.extinction), slopeT * halfLevel * 1.01 + 1e-6)
            << value;
        for (int c = 0; c < 3; ++c) {
            const double colorError = std::abs(level.color[c] - exact.color[c]);
            EXPECT_LE(colorError, slopeC * halfLevel * 1.01 + 1e-6) << value;
            largest = std::max(largest, colorError);
        }
    }
    EXPECT_GT(largest, 0.0) << "values between levels should move";
    // On a level (multiples of 1/32768 of the range) and outside the range: exact.
    for (const float t : {0.0f, 0.25f, 0.5f, 1.0f, 12345.0f / 32768.0f}) {
        const float value = scale.range.x + t * (scale.range.y - scale.range.x);
        const Classification exact = tf->classify(value, scale);
        const Classification level = tf->classifyLevel(value, scale);
        EXPECT_EQ(level.extinction, exact.extinction) << t;
        EXPECT_EQ(level.color, exact.color) << t;
    }
    EXPECT_EQ(tf->classifyLevel(-100.0f, scale).extinction,
              tf->classify(-100.0f, scale).extinction);
    EXPECT_EQ(tf->classifyLevel(std::numeric_limits<float>::quiet_NaN(), scale).extinction, 0.0f);
}

TEST(TransferFunction, classifyingAGridChecksTheFields) {
    volume::DenseScalarGrid grid(volume::GridGeometry({1, 1, 1}));
    const auto tf = TransferFunction::create();
    tf->emission = -1.0f;
    EXPECT_EQ(errorOf<DataError>([&] { tf->classify(grid); }),
              "TransferFunction: emission must be finite and not negative, got -1");
}

TEST(TransferFunction, putsItselfIntoTheState) {
    const auto root = sg::Separator::create();
    const auto tf = TransferFunction::create();
    const auto probe = test::StateProbe::create();
    const TransferFunction* seen = nullptr;
    probe->visit = [&](sg::Action& action) {
        seen = action.state().get<TransferFunctionElement>().transferFunction;
    };
    root->addChild(tf);
    root->addChild(probe);
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(seen, tf.get());
}

} // namespace
} // namespace texsplat::nodes
