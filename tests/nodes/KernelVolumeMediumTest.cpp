#include "nodes/render/KernelVolumeMedium.h"

#include "nodes/kernel/CubicKernel.h"
#include "scenegraph/Declare.h"
#include "scenegraph/Error.h"
#include "scenegraph/Node.h"
#include "scenegraph/actions/RayCastAction.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::render {
namespace {

// Queues one medium under an orthographic camera looking down −z from z = 10 at the square
// [centre − half, centre + half]² (x, y).
class MediumNode : public sg::Declare<MediumNode, sg::Node> {
public:
    static constexpr const char* kTypeName = "TestKernelMediumNode";
    std::shared_ptr<const sg::RayCastMedium> medium;
    glm::vec2 centre{0.0f};
    float half = 2.0f;

    void doAction(sg::Action& action) override {
        if (auto* rayCast = dynamic_cast<sg::RayCastAction*>(&action)) {
            rayCast->setCamera(glm::lookAt(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f),
                                           glm::vec3(0.0f, 1.0f, 0.0f)),
                               glm::ortho(centre.x - half, centre.x + half, centre.y - half,
                                          centre.y + half, 1.0f, 20.0f));
            rayCast->addMedium(medium);
        }
    }
};

// A grid of `dims` voxels, all empty but `voxel` at `ijk`.
std::shared_ptr<octree::ClassifiedGrid> oneVoxel(glm::u64vec3 dims, glm::u64vec3 ijk,
                                                 glm::vec3 color, float tau,
                                                 glm::dvec3 spacing = glm::dvec3(1.0),
                                                 glm::dvec3 origin = glm::dvec3(0.0)) {
    auto grid = std::make_shared<octree::ClassifiedGrid>(dims, spacing, origin);
    grid->setVoxel(ijk, color, tau);
    return grid;
}

struct Rendered {
    std::vector<float> rgba;
    int size;
    glm::vec2 centre;
    float half;

    // Root-space x, y of pixel (x, y)'s centre.
    glm::vec2 position(int x, int y) const {
        return {centre.x - half + (x + 0.5f) * 2.0f * half / size,
                centre.y + half - (y + 0.5f) * 2.0f * half / size};
    }
    glm::vec4 pixel(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * size + x) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
};

Rendered render(std::shared_ptr<const sg::RayCastMedium> medium, int size, float step,
                glm::vec2 centre = glm::vec2(0.0f), float half = 2.0f) {
    MediumNode::Ptr node = MediumNode::create();
    node->medium = std::move(medium);
    node->centre = centre;
    node->half = half;
    sg::RayCastAction action(size, size);
    action.setStepSize(step);
    action.setThreadCount(1);
    action.render(*node);
    return {action.readColor(), size, centre, half};
}

// Largest |red − expected(x, y)| over the image.
double maxError(const Rendered& image, const std::function<double(glm::vec2)>& expected) {
    double worst = 0.0;
    for (int y = 0; y < image.size; ++y) {
        for (int x = 0; x < image.size; ++x) {
            worst = std::max(worst, std::abs(image.pixel(x, y).r - expected(image.position(x, y))));
        }
    }
    return worst;
}

const kernel::CubicKernel& paper() {
    static const kernel::CubicKernel kernel = kernel::CubicKernel::paper();
    return kernel;
}

TEST(KernelVolumeMedium, oneVoxelSeenOrthographicallyIsItsFootprintTimesItsColor) {
    const glm::vec3 color(1.0f, 0.5f, 0.25f);
    const Rendered image =
        render(std::make_shared<KernelVolumeMedium>(oneVoxel({1, 1, 1}, {0, 0, 0}, color, 0.0f),
                                                    glm::mat4(1.0f)),
               24, sg::RayCastAction::kDefaultStepSize);
    const double error =
        maxError(image, [](glm::vec2 p) { return paper().footprint(glm::length(glm::dvec2(p))); });
    RecordProperty("max_error_default_step", std::to_string(error));
    EXPECT_LT(error, 2e-4); // f(0) = 0.93: relative 2e-4
    const glm::vec4 middle = image.pixel(12, 12);
    EXPECT_NEAR(middle.g / middle.r, 0.5f, 1e-6f);
    EXPECT_NEAR(middle.b / middle.r, 0.25f, 1e-6f);
    EXPECT_EQ(middle.a, 0.0f);
}

TEST(KernelVolumeMedium, emissionConvergesQuadraticallyWithStepSize) {
    const auto medium = std::make_shared<KernelVolumeMedium>(
        oneVoxel({1, 1, 1}, {0, 0, 0}, glm::vec3(1.0f), 0.0f), glm::mat4(1.0f));
    std::vector<double> errors;
    for (float step : {1.0f, 0.5f, 0.25f, 0.125f}) {
        errors.push_back(maxError(render(medium, 12, step), [](glm::vec2 p) {
            return paper().footprint(glm::length(glm::dvec2(p)));
        }));
        RecordProperty("max_error_step_" + std::to_string(step), std::to_string(errors.back()));
    }
    // Measured max errors: 1.1e-3, 6.0e-4, 4.1e-5, 6e-6 (f(0) = 0.93). The steps are fitted to
    // the support's chord (4, 7, 13, 25 steps), so single halvings are irregular; over three
    // halvings the error falls like Δs² (64×) or faster.
    for (std::size_t i = 1; i < errors.size(); ++i) {
        EXPECT_LT(errors[i], errors[i - 1]) << "step index " << i;
    }
    EXPECT_GT(errors.front() / errors.back(), 40.0);
    EXPECT_LT(errors.back(), 2e-5);
}

// One voxel with emission C and extinction τ: c = (C/τ)·τ(x), so I = (C/τ)(1 − e^(−τ f(r))),
// from optically thin (τ f ≪ 1: I → C f) to thick (I → C/τ).
TEST(KernelVolumeMedium, oneAbsorbingVoxelMatchesTheClosedFormFromThinToThick) {
    for (float tau : {1e-8f, 1e-3f, 1.0f, 10.0f, 1e3f, 1e8f}) {
        const Rendered image = render(
            std::make_shared<KernelVolumeMedium>(
                oneVoxel({1, 1, 1}, {0, 0, 0}, glm::vec3(1.0f), tau), glm::mat4(1.0f)),
            12, 0.125f);
        double worst = 0.0;
        for (int y = 0; y < image.size; ++y) {
            for (int x = 0; x < image.size; ++x) {
                const double f = paper().footprint(glm::length(glm::dvec2(image.position(x, y))));
                const double x0 = static_cast<double>(tau) * f;
                const double expected = x0 > 0.0 ? -std::expm1(-x0) / tau : 0.0;
                const double alpha = -std::expm1(-x0);
                const glm::vec4 pixel = image.pixel(x, y);
                // Relative to the pixel's saturation value C/τ or its thin value C·f(0).
                const double scale = std::min(1.0 / tau, paper().footprint(0.0));
                worst = std::max(worst, std::abs(pixel.r - expected) / scale);
                EXPECT_NEAR(pixel.a, alpha, 1e-3) << "tau " << tau;
            }
        }
        EXPECT_LT(worst, 1e-3) << "tau " << tau;
    }
}

TEST(KernelVolumeMedium, anisotropicSpacingStretchesTheKernelLikeTheSplats) {
    // Spacing 2 along the view: twice the path through h(S⁻¹x), so 2 f(r).
    const Rendered deep = render(
        std::make_shared<KernelVolumeMedium>(
            oneVoxel({1, 1, 1}, {0, 0, 0}, glm::vec3(1.0f), 0.0f, {1.0, 1.0, 2.0}),
            glm::mat4(1.0f)),
        12, 0.25f);
    EXPECT_LT(maxError(deep, [](glm::vec2 p) { return 2.0 * paper().footprint(glm::length(glm::dvec2(p))); }),
              4e-4);
    // Spacing 2 along x: the footprint is an ellipse, f(√((x/2)² + y²)).
    const Rendered wide = render(
        std::make_shared<KernelVolumeMedium>(
            oneVoxel({1, 1, 1}, {0, 0, 0}, glm::vec3(1.0f), 0.0f, {2.0, 1.0, 1.0}),
            glm::mat4(1.0f)),
        12, 0.25f, glm::vec2(0.0f), 3.5f);
    EXPECT_LT(maxError(wide, [](glm::vec2 p) {
                  return paper().footprint(std::hypot(p.x / 2.0, static_cast<double>(p.y)));
              }),
              2e-4);
}

TEST(KernelVolumeMedium, aScalingTransformChangesTheSizeNotTheOpticalDepth) {
    const glm::mat4 model = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f));
    const Rendered image = render(std::make_shared<KernelVolumeMedium>(
                                      oneVoxel({1, 1, 1}, {0, 0, 0}, glm::vec3(1.0f), 0.0f), model),
                                  12, 0.25f, glm::vec2(0.0f), 3.5f);
    EXPECT_LT(maxError(image, [](glm::vec2 p) { return paper().footprint(glm::length(glm::dvec2(p)) / 2.0); }),
              2e-4);
}

TEST(KernelVolumeMedium, emptyBricksAreSkippedWithoutChangingTheImage) {
    // One voxel in the middle of a 40³ grid: only the 3×3×3 bricks around it are active.
    const auto sparse = std::make_shared<KernelVolumeMedium>(
        oneVoxel({40, 40, 40}, {20, 20, 20}, glm::vec3(1.0f), 0.0f, glm::dvec3(1.0),
                 glm::dvec3(-20.0)),
        glm::mat4(1.0f));
    EXPECT_EQ(sparse->brickCount(), 7u * 7u * 7u);
    EXPECT_EQ(sparse->activeBrickCount(), 27u);
    // A voxel at a brick corner still reaches into the neighbouring bricks' sample positions.
    const auto corner = std::make_shared<KernelVolumeMedium>(
        oneVoxel({40, 40, 40}, {15, 16, 24}, glm::vec3(1.0f), 0.0f, glm::dvec3(1.0),
                 glm::dvec3(-15.0, -16.0, -24.0)),
        glm::mat4(1.0f));
    const auto footprint = [](glm::vec2 p) { return paper().footprint(glm::length(glm::dvec2(p))); };
    EXPECT_LT(maxError(render(sparse, 12, 0.25f), footprint), 2e-4);
    EXPECT_LT(maxError(render(corner, 12, 0.25f), footprint), 2e-4);
    // An oblique ray through the grid crosses many bricks: the runs merge and stay exact.
    sg::RayCastRay ray;
    ray.origin = glm::vec3(-30.0f, -25.0f, -28.0f);
    ray.direction = glm::normalize(glm::vec3(1.0f, 0.9f, 1.1f));
    std::vector<sg::RayCastMedium::Interval> intervals;
    sparse->intervals(ray, 0.0f, 100.0f, 0.5f, intervals);
    ASSERT_EQ(intervals.size(), 1u);
    const float closest = glm::dot(-ray.origin, ray.direction);
    EXPECT_LT(intervals[0].t0, closest - 1.6f);
    EXPECT_GT(intervals[0].t1, closest + 1.6f);
    EXPECT_LT(intervals[0].t1 - intervals[0].t0, 45.0f); // 3 bricks, not the 68-long chord
    EXPECT_NEAR(intervals[0].step, 0.5f, 1e-6f);
}

TEST(KernelVolumeMedium, extremeValuesAndStepsGiveFiniteImages) {
    for (float tau : {0.0f, 1e-8f, 1.0f, 1e8f}) {
        for (float emission : {1e-30f, 1.0f, 1e30f}) {
            auto grid = std::make_shared<octree::ClassifiedGrid>(glm::u64vec3(3, 2, 4),
                                                                 glm::dvec3(1.0), glm::dvec3(-1.0));
            for (std::uint64_t k = 0; k < 4; ++k) {
                grid->setVoxel({k % 3, k % 2, k}, glm::vec3(emission), tau);
            }
            const auto medium = std::make_shared<KernelVolumeMedium>(grid, glm::mat4(1.0f));
            for (float step : {1e-4f, 0.25f, 1.0f, 1e3f}) {
                const Rendered image = render(medium, 4, step);
                for (float value : image.rgba) {
                    ASSERT_TRUE(std::isfinite(value) && value >= 0.0f)
                        << "tau " << tau << " emission " << emission << " step " << step;
                }
            }
        }
    }
}

TEST(KernelVolumeMedium, rejectsASingularModelMatrix) {
    try {
        KernelVolumeMedium(oneVoxel({1, 1, 1}, {0, 0, 0}, glm::vec3(1.0f), 0.0f),
                           glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 1.0f)));
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "KernelVolumeMedium: the model matrix must be finite and invertible");
    }
}

} // namespace
} // namespace texsplat::render
