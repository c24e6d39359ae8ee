#include "nodes/volume/Aerogel.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/Magnitude.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::volume {
namespace {

const std::vector<Fiber> kOneFiber = {{{0.5, 0.5, 0.0}, {0.5, 0.5, 1.0}, 0.1}};
const glm::dvec3 kInflow(1.0, 0.0, 0.0);

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], 1e-12) << "component " << c;
}

TEST(Aerogel, flowAroundOneFiberHasTheClosedForm) {
    const double noSlipAtOneRadius = 1.0 - std::exp(-1.0);
    // Beside the fiber (flow along the surface): the doublet speeds the flow up by (R/rho)².
    expectNear(aerogelVelocity({0.5, 0.7, 0.5}, kOneFiber, kInflow),
               {1.25 * noSlipAtOneRadius, 0.0, 0.0});
    // Upstream of it (flow towards the surface): slowed down by (R/rho)².
    expectNear(aerogelVelocity({0.3, 0.5, 0.5}, kOneFiber, kInflow),
               {0.75 * noSlipAtOneRadius, 0.0, 0.0});
    // On the axis past a cap no doublet remains, only the no-slip factor of the cap distance.
    expectNear(aerogelVelocity({0.5, 0.5, 1.2}, kOneFiber, kInflow),
               {1.0 - std::exp(-4.0), 0.0, 0.0});
}

TEST(Aerogel, speedVanishesInsideAndOnFibers) {
    EXPECT_EQ(aerogelVelocity({0.55, 0.5, 0.5}, kOneFiber, kInflow), glm::dvec3(0.0));
    EXPECT_EQ(aerogelVelocity({0.6, 0.5, 0.5}, kOneFiber, kInflow), glm::dvec3(0.0));
    EXPECT_LT(glm::length(aerogelVelocity({0.6 + 1e-4, 0.5, 0.5}, kOneFiber, kInflow)), 1e-5);
    EXPECT_EQ(aerogelVelocity({0.3, 0.2, 0.1}, {}, kInflow), kInflow);
}

TEST(Aerogel, generatesSeededFibersAndTheirFlow) {
    AerogelParameters parameters;
    parameters.dims = {24, 24, 24};
    parameters.fiberCount = 12;
    const AerogelField field = generateAerogel(parameters);
    ASSERT_EQ(field.fibers.size(), 12u);
    for (const Fiber& fiber : field.fibers) {
        EXPECT_GE(fiber.radius, parameters.minRadius);
        EXPECT_LT(fiber.radius, parameters.maxRadius);
        const double length = glm::length(fiber.end - fiber.start);
        EXPECT_GE(length, parameters.minLength - 1e-12);
        EXPECT_LT(length, parameters.maxLength);
    }
    EXPECT_EQ(field.velocity->geometry(),
              GridGeometry({24, 24, 24}, glm::dvec3(0.0), glm::dvec3(1.0 / 23)));
    const GridStatistics speed = field.velocity->statistics();
    EXPECT_EQ(speed.nonFiniteCount, 0);
    EXPECT_EQ(speed.minimum, 0.0) << "some voxels lie inside fibers";
    EXPECT_GT(speed.maximum, 1.0) << "flow speeds up between fibers";
    EXPECT_LT(speed.maximum, 3.0);
    const glm::i64vec3 index(5, 17, 9);
    EXPECT_EQ(field.velocity->value(index),
              glm::vec3(aerogelVelocity(field.velocity->geometry().indexToWorld(glm::dvec3(index)),
                                        field.fibers, parameters.inflow)));

    const AerogelField again = generateAerogel(parameters);
    EXPECT_EQ(again.fibers[7].end, field.fibers[7].end);
    EXPECT_EQ(dynamic_cast<const DenseVectorGrid&>(*again.velocity).values(),
              dynamic_cast<const DenseVectorGrid&>(*field.velocity).values());
    parameters.seed = 2;
    EXPECT_NE(generateAerogel(parameters).fibers[7].end, field.fibers[7].end);
}

TEST(Aerogel, rejectsBadParameters) {
    AerogelParameters parameters;
    parameters.minRadius = 0.05;
    parameters.maxRadius = 0.01;
    try {
        generateAerogel(parameters);
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "aerogel: radius range must be positive and increasing, got 0.05 to 0.01");
    }
    parameters = AerogelParameters();
    parameters.fiberCount = -1;
    try {
        generateAerogel(parameters);
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "aerogel: fiber count must be at least 0, got -1");
    }
    parameters = AerogelParameters();
    parameters.inflow = {1.0, NAN, 0.0};
    try {
        generateAerogel(parameters);
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "aerogel: inflow must be finite, got 1 nan 0");
    }
}

} // namespace
} // namespace texsplat::volume
