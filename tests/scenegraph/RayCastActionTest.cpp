#include "scenegraph/actions/RayCastAction.h"

#include "scenegraph/Declare.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/Log.h"
#include "scenegraph/Node.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace texsplat::sg {
namespace {

// A medium between the planes z = zFront and z = zBack (zFront > zBack: the camera looks down
// −z) with emission and extinction given as functions of the depth s = zFront − z into it.
class SlabMedium final : public RayCastMedium {
public:
    double zFront = 0.5;
    double zBack = -0.5;
    std::function<glm::vec4(double depth)> medium = [](double) { return glm::vec4(0.0f); };

    void intervals(const RayCastRay& ray, float tMin, float tMax, float stepVoxels,
                   std::vector<Interval>& out) const override {
        if (ray.direction.z >= 0.0f) {
            return;
        }
        Interval interval;
        interval.t0 = std::max(tMin, static_cast<float>((zFront - ray.origin.z) / ray.direction.z));
        interval.t1 = std::min(tMax, static_cast<float>((zBack - ray.origin.z) / ray.direction.z));
        interval.step = stepVoxels; // one "voxel" is one unit
        if (interval.t1 > interval.t0) {
            out.push_back(interval);
        }
    }

    Sample sample(const RayCastRay& ray, float t) const override {
        const double z = static_cast<double>(ray.origin.z) + static_cast<double>(t) * ray.direction.z;
        if (z > zFront || z < zBack) {
            return Sample(0.0f);
        }
        return medium(zFront - z);
    }
};

// An opaque plane z = zPlane of one color.
class PlaneSurface final : public RayCastSurface {
public:
    float zPlane = 0.0f;
    glm::vec4 color{1.0f, 0.0f, 0.0f, 1.0f};

    bool intersect(const RayCastRay& ray, float tMin, float tMax, float& t,
                   glm::vec4& hitColor) const override {
        if (ray.direction.z == 0.0f) {
            return false;
        }
        const float distance = (zPlane - ray.origin.z) / ray.direction.z;
        if (distance > tMin && distance < tMax) {
            t = distance;
            hitColor = color;
            return true;
        }
        return false;
    }
};

// Sets an orthographic camera looking down −z from z = 10 at [−1, 1]² and queues its media and
// surfaces.
class WorkNode : public Declare<WorkNode, Node> {
public:
    static constexpr const char* kTypeName = "TestRayCastWorkNode";
    std::vector<std::shared_ptr<const RayCastMedium>> media;
    std::vector<std::shared_ptr<const RayCastSurface>> surfaces;

    void doAction(Action& action) override {
        auto* rayCast = dynamic_cast<RayCastAction*>(&action);
        if (!rayCast) {
            return;
        }
        rayCast->setCamera(glm::lookAt(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f),
                                       glm::vec3(0.0f, 1.0f, 0.0f)),
                           glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 20.0f));
        for (const auto& medium : media) {
            rayCast->addMedium(medium);
        }
        for (const auto& surface : surfaces) {
            rayCast->addSurface(surface);
        }
    }
};

std::shared_ptr<SlabMedium> constantSlab(double length, glm::vec3 emission, float tau) {
    auto slab = std::make_shared<SlabMedium>();
    slab->zFront = length / 2;
    slab->zBack = -length / 2;
    slab->medium = [emission, tau](double) { return glm::vec4(emission, tau); };
    return slab;
}

// The centre pixel of a render of `node` (an even-sized image: pixel (n/2, n/2)).
std::vector<float> renderPixels(WorkNode& node, int size, float step, int threads = 1,
                                glm::vec4 background = glm::vec4(0.0f)) {
    RayCastAction action(size, size);
    action.setStepSize(step);
    action.setThreadCount(threads);
    action.setBackground(background);
    action.render(node);
    return action.readColor();
}

glm::dvec4 centre(const std::vector<float>& rgba, int size) {
    const std::size_t i = (static_cast<std::size_t>(size / 2) * size + size / 2) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

template <typename Exception, typename Function> std::string errorOf(Function function) {
    try {
        function();
    } catch (const Exception& error) {
        return error.what();
    }
    return "no such error";
}

TEST(RayCastAction, constantSlabMatchesTheClosedFormForAnyStep) {
    const double length = 1.5;
    const double tau = 2.0;
    const glm::vec3 emission(1.0f, 0.5f, 0.25f);
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(constantSlab(length, emission, static_cast<float>(tau)));
    const double transmittance = std::exp(-tau * length);
    const glm::vec4 background(0.0f, 0.0f, 0.5f, 0.5f);
    // Exact exponential steps are exact for a constant medium, whatever the step.
    for (float step : {0.01f, 0.25f, 1.0f, 100.0f}) {
        const glm::dvec4 pixel = centre(renderPixels(*node, 4, step, 1, background), 4);
        EXPECT_NEAR(pixel.r, 1.0 / tau * (1.0 - transmittance), 1e-6) << step;
        EXPECT_NEAR(pixel.g, 0.5 / tau * (1.0 - transmittance), 1e-6) << step;
        EXPECT_NEAR(pixel.b, 0.25 / tau * (1.0 - transmittance) + 0.5 * transmittance, 1e-6);
        EXPECT_NEAR(pixel.a, 1.0 - transmittance + 0.5 * transmittance, 1e-6) << step;
    }
}

TEST(RayCastAction, thinAndThickMediaFromTauOneEMinusEightToOneEEight) {
    const double length = 1.0;
    for (double tau : {1e-8, 1e-5, 1e-2, 1.0, 10.0, 1e3, 1e8}) {
        WorkNode::Ptr node = WorkNode::create();
        node->media.push_back(constantSlab(length, glm::vec3(1.0f), static_cast<float>(tau)));
        const glm::dvec4 pixel = centre(renderPixels(*node, 2, 0.1f), 2);
        // c·L·φ(τL) with φ(x) = −expm1(−x)/x: thin → L (no cancellation), thick → 1/τ.
        const long double x = tau * length;
        const long double expected = -std::expm1(-x) / x * length;
        const long double alpha = -std::expm1(-x);
        EXPECT_NEAR(pixel.r / expected, 1.0, 1e-6) << "tau " << tau;
        EXPECT_NEAR(pixel.a / alpha, 1.0, 1e-6) << "tau " << tau;
    }
}

// c = 1, τ(s) = 2s on s ∈ [0, 1]: T(s) = exp(−s²), I = ∫₀¹ exp(−s²) ds = (√π / 2) erf(1).
TEST(RayCastAction, midpointExponentialStepsConvergeQuadraticallyWithStepSize) {
    auto slab = std::make_shared<SlabMedium>();
    slab->zFront = 0.5;
    slab->zBack = -0.5;
    slab->medium = [](double s) { return glm::vec4(1.0f, 1.0f, 1.0f, static_cast<float>(2.0 * s)); };
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(slab);
    const double exact = std::sqrt(std::acos(-1.0)) / 2.0 * std::erf(1.0);
    std::vector<double> errors;
    for (float step : {0.5f, 0.25f, 0.125f, 0.0625f, 0.03125f}) {
        errors.push_back(std::abs(centre(renderPixels(*node, 2, step), 2).r - exact));
        RecordProperty("error_at_step_" + std::to_string(step), std::to_string(errors.back()));
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
        // Second order: halving the step quarters the error (3.5 .. 4.5 allows float noise).
        EXPECT_GT(errors[i - 1] / errors[i], 3.5) << "step index " << i;
        EXPECT_LT(errors[i - 1] / errors[i], 4.5) << "step index " << i;
    }
    // Measured: 3.0e-2 at step 1/2 down to 1.2e-4 at 1/32, ratio 3.9–4.0 (error ≈ 0.12·Δs²).
    EXPECT_LT(errors.back(), 1.5e-4);
}

TEST(RayCastAction, overlappingMediaAddTheirEmissionAndExtinction) {
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(constantSlab(1.0, glm::vec3(1.0f, 0.0f, 0.0f), 0.0f));
    node->media.push_back(constantSlab(0.5, glm::vec3(0.0f, 1.0f, 0.0f), 0.0f));
    const glm::dvec4 pixel = centre(renderPixels(*node, 2, 0.3f), 2);
    EXPECT_NEAR(pixel.r, 1.0, 1e-6);
    EXPECT_NEAR(pixel.g, 0.5, 1e-6);
    EXPECT_EQ(pixel.a, 0.0);
}

TEST(RayCastAction, anOpaqueSurfaceEndsTheRayBehindTheMediumInFront) {
    const double tau = 1.0;
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(constantSlab(2.0, glm::vec3(1.0f), static_cast<float>(tau)));
    auto plane = std::make_shared<PlaneSurface>();
    plane->zPlane = 0.0f; // half of the slab in front
    node->surfaces.push_back(plane);
    const glm::dvec4 pixel = centre(renderPixels(*node, 2, 0.25f), 2);
    const double transmittance = std::exp(-tau * 1.0);
    EXPECT_NEAR(pixel.r, (1.0 - transmittance) / tau + transmittance * 1.0, 1e-6);
    EXPECT_NEAR(pixel.g, (1.0 - transmittance) / tau, 1e-6);
    EXPECT_NEAR(pixel.a, 1.0, 1e-6);
}

TEST(RayCastAction, stiffAndExtremeValuesGiveFiniteImages) {
    for (float tau : {0.0f, 1e-30f, 1e-8f, 1e8f, 1e30f, 3e38f}) {
        for (float emission : {0.0f, 1e-30f, 1.0f, 1e30f, 3e38f}) {
            WorkNode::Ptr node = WorkNode::create();
            node->media.push_back(constantSlab(1.0, glm::vec3(emission), tau));
            // Steps below the float resolution of t (here about 1e-6): see
            // lengthensStepsBelowTheFloatResolutionWithOneWarningPerRender.
            for (float step : {1e-4f, 0.01f, 1.0f, 1e6f}) {
                const std::vector<float> rgba = renderPixels(*node, 2, step);
                for (float value : rgba) {
                    ASSERT_TRUE(std::isfinite(value) && value >= 0.0f)
                        << "tau " << tau << " emission " << emission << " step " << step;
                }
                EXPECT_LE(rgba[3], 1.0f);
            }
        }
    }
}

// The slab is one piece of the ray; steps used to be capped at 16384 per piece, whatever the
// piece's length (for a run of active bricks, a step of about 0.02 voxel on a 128³ grid).
TEST(RayCastAction, aLongPieceTakesAsManyStepsAsTheStepSizeAsks) {
    auto samples = std::make_shared<std::atomic<long long>>(0);
    auto slab = constantSlab(1.0, glm::vec3(1.0f), 1.0f);
    slab->medium = [samples](double) {
        samples->fetch_add(1, std::memory_order_relaxed);
        return glm::vec4(1.0f);
    };
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(slab);
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&warnings](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning) {
            warnings.emplace_back(message);
        }
    });
    const glm::dvec4 pixel = centre(renderPixels(*node, 2, 1.0f / 32768.0f), 2);
    setLogSink(previous);
    // 4 rays through 1 unit at 1/32768: 32768 steps each (32769 if rounding of t lengthens
    // the piece by an ulp).
    EXPECT_GE(samples->load(), 4 * 32768);
    EXPECT_LE(samples->load(), 4 * 32769);
    EXPECT_NEAR(pixel.r, 1.0 - std::exp(-1.0), 1e-6);
    EXPECT_EQ(warnings, std::vector<std::string>{});
}

// The slab lies at t ∈ [8.5, 9.5] from the near plane, where floats are 9.5e-7 apart: a step
// of 1e-9 is lengthened to 9.5·FLT_EPSILON = 1.1e-6 (8.8·10⁵ steps per ray, not 10⁹), with
// one warning per render however many rays and threads hit the limit.
TEST(RayCastAction, lengthensStepsBelowTheFloatResolutionWithOneWarningPerRender) {
    const float tau = 1.0f;
    auto samples = std::make_shared<std::atomic<long long>>(0);
    auto slab = constantSlab(1.0, glm::vec3(1.0f), tau);
    slab->medium = [samples, tau](double) {
        samples->fetch_add(1, std::memory_order_relaxed);
        return glm::vec4(1.0f, 1.0f, 1.0f, tau);
    };
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(slab);
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&warnings](LogLevel level, std::string_view message) {
        warnings.push_back(std::string(toString(level)) + ": " + std::string(message));
    });
    RayCastAction action(2, 2);
    action.setStepSize(1e-9f);
    action.setThreadCount(2);
    action.render(*node);
    const glm::dvec4 pixel = centre(action.readColor(), 2);
    const long long firstSamples = samples->load();
    action.render(*node);
    setLogSink(previous);

    const std::string expected =
        "warning: RayCastAction: the step of 1e-09 voxels is finer than float positions along "
        "some rays can resolve; there it was lengthened to the float spacing (about 1.2e-7 of "
        "the distance from the near plane)";
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0], expected);
    EXPECT_EQ(warnings[1], expected);
    // Per ray 1 / (9.5 · FLT_EPSILON) = 8.8·10⁵ steps.
    EXPECT_GT(firstSamples, 4 * 800000LL);
    EXPECT_LT(firstSamples, 4 * 900000LL);
    // Exact for a constant medium whatever the step.
    EXPECT_NEAR(pixel.r, (1.0 - std::exp(-1.0)) / tau, 1e-6);
    EXPECT_NEAR(pixel.a, 1.0 - std::exp(-1.0), 1e-6);
}

// `--raycast-step 1e-7` on a 16^3 volume ran for hours without a word; render() now warns with
// this estimate above RayCastAction::kSamplesToWarn before integrating.
TEST(RayCastAction, estimatesTheSamplesOfARenderBeforeIntegrating) {
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(constantSlab(1.0, glm::vec3(1.0f), 1.0f));
    RayCastAction action(64, 48);
    EXPECT_EQ(action.estimatedSamples(0.25f), 0.0); // nothing queued yet
    action.apply(*node);
    // Every ray crosses the unit slab: 4 steps of 0.25 (5 when rounding of t lengthens it).
    EXPECT_GE(action.estimatedSamples(0.25f), 64.0 * 48 * 4);
    EXPECT_LE(action.estimatedSamples(0.25f), 64.0 * 48 * 5);
    // Below the float resolution of t a step counts as the float spacing, as when integrating:
    // 8.8e5 a ray at t = 9.5.
    EXPECT_GT(action.estimatedSamples(1e-9f), 64.0 * 48 * 800000);
    EXPECT_LT(action.estimatedSamples(1e-9f), 64.0 * 48 * 900000);
}

TEST(RayCastAction, imagesDoNotDependOnTheThreadCount) {
    auto slab = std::make_shared<SlabMedium>();
    slab->medium = [](double s) {
        return glm::vec4(static_cast<float>(s), 1.0f, 0.5f, static_cast<float>(1.0 + s));
    };
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(slab);
    const std::vector<float> one = renderPixels(*node, 17, 0.1f, 1);
    EXPECT_EQ(renderPixels(*node, 17, 0.1f, 2), one);
    EXPECT_EQ(renderPixels(*node, 17, 0.1f, 5), one);
    EXPECT_EQ(renderPixels(*node, 17, 0.1f, 0), one);
}

TEST(RayCastAction, pixelCentresFollowTheTopRowFirstConvention) {
    WorkNode::Ptr node = WorkNode::create();
    RayCastAction action(4, 2);
    action.apply(*node);
    float tMin = 0.0f;
    float tMax = 0.0f;
    const RayCastRay topLeft = action.pixelRay(0, 0, tMin, tMax);
    EXPECT_NEAR(topLeft.origin.x, -0.75f, 1e-6f);
    EXPECT_NEAR(topLeft.origin.y, 0.5f, 1e-6f);
    EXPECT_NEAR(topLeft.origin.z, 9.0f, 1e-5f); // the near plane
    EXPECT_NEAR(topLeft.direction.z, -1.0f, 1e-6f);
    EXPECT_NEAR(tMax, 19.0f, 1e-4f);
    const RayCastRay bottomRight = action.pixelRay(3, 1, tMin, tMax);
    EXPECT_NEAR(bottomRight.origin.x, 0.75f, 1e-6f);
    EXPECT_NEAR(bottomRight.origin.y, -0.5f, 1e-6f);
}

TEST(RayCastAction, progressReachesOneAndFalseCancels) {
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(constantSlab(1.0, glm::vec3(1.0f), 1.0f));
    RayCastAction action(8, 8);
    std::vector<double> fractions;
    action.setProgress([&fractions](double fraction) {
        fractions.push_back(fraction);
        return true;
    });
    action.render(*node);
    ASSERT_FALSE(fractions.empty());
    EXPECT_EQ(fractions.back(), 1.0);
    for (std::size_t i = 1; i < fractions.size(); ++i) {
        EXPECT_GE(fractions[i], fractions[i - 1]);
    }

    action.setProgress([](double) { return false; });
    const std::string message = errorOf<RenderCancelled>([&] { action.render(*node); });
    EXPECT_EQ(message.rfind("RayCastAction::render(): cancelled by the progress callback", 0), 0u)
        << message;
    for (float value : action.readColor()) {
        ASSERT_EQ(value, 0.0f);
    }
}

TEST(RayCastAction, aThrowingProgressCallbackStopsTheWorkersAndPropagates) {
    WorkNode::Ptr node = WorkNode::create();
    node->media.push_back(constantSlab(1.0, glm::vec3(1.0f), 1.0f));
    RayCastAction action(64, 64);
    action.setThreadCount(2);
    action.setStepSize(0.001f);
    action.setProgress([](double) -> bool { throw std::runtime_error("stop here"); });
    EXPECT_EQ(errorOf<std::runtime_error>([&] { action.render(*node); }), "stop here");
}

TEST(RayCastAction, withoutWorkTheImageIsTheBackground) {
    Group::Ptr empty = Group::create();
    RayCastAction action(3, 2);
    action.setBackground(glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
    action.render(*empty);
    const std::vector<float> rgba = action.readColor();
    ASSERT_EQ(rgba.size(), 24u);
    EXPECT_EQ(rgba[22], 0.3f);
    EXPECT_EQ(rgba[23], 0.4f);
}

TEST(RayCastAction, reportsBadSizesStepsAndThreadCounts) {
    EXPECT_EQ(errorOf<DataError>([] { RayCastAction(0, 4); }),
              "RayCastAction: image size 0 x 4 must be positive and at most 32768 per side");
    RayCastAction action(2, 2);
    EXPECT_EQ(errorOf<DataError>([&] { action.setStepSize(0.0f); }),
              "RayCastAction: step size must be finite and > 0 voxels, got 0.000000");
    EXPECT_EQ(errorOf<DataError>([&] { action.setStepSize(std::nanf("")); }).substr(0, 54),
              "RayCastAction: step size must be finite and > 0 voxels");
    EXPECT_EQ(errorOf<DataError>([&] { action.setThreadCount(-1); }),
              "RayCastAction: thread count must be >= 0, got -1");
    EXPECT_EQ(action.stepSize(), RayCastAction::kDefaultStepSize);
}

} // namespace
} // namespace texsplat::sg
