#include "nodes/volume/JetStream.h"

#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/Magnitude.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

namespace texsplat::volume {
namespace {

const std::vector<float>& values(const ScalarGridPtr& grid) {
    return dynamic_cast<const DenseScalarGrid&>(*grid).values();
}

TEST(JetStream, coversTheLatitudeLongitudeAltitudeBox) {
    const JetStreamField field = generateJetStream({});
    const GridGeometry expected({96, 48, 24}, {-140.0, 15.0, 0.0},
                                {90.0 / 95, 50.0 / 47, 16.0 / 23});
    EXPECT_EQ(field.wind->geometry(), expected);
    EXPECT_EQ(field.cloudiness->geometry(), expected);
    EXPECT_EQ(field.wind->statistics().nonFiniteCount, 0);
    EXPECT_EQ(field.cloudiness->statistics().nonFiniteCount, 0);
}

TEST(JetStream, windsPeakNearTheTropopause) {
    const JetStreamField field = generateJetStream({});
    const ScalarGridPtr speed = magnitudeGrid(*field.wind);
    const GridStatistics statistics = speed->statistics();
    EXPECT_GT(statistics.maximum, 45.0);
    EXPECT_LT(statistics.maximum, 80.0);
    glm::i64vec3 fastest(0);
    speed->forEachActive([&](const glm::i64vec3& index, const float& value) {
        if (value == float(statistics.maximum))
            fastest = index;
    });
    const double altitude = speed->geometry().indexToWorld(glm::dvec3(fastest)).z;
    EXPECT_GT(altitude, 8.0);
    EXPECT_LT(altitude, 13.0);
    // Near the ground only the weak westerlies remain.
    EXPECT_LT(speed->value({10, 10, 0}), 5.0f);
}

TEST(JetStream, cloudinessIsAPercentageWithClearAndCloudySky) {
    const JetStreamField field = generateJetStream({});
    const GridStatistics statistics = field.cloudiness->statistics();
    EXPECT_EQ(statistics.minimum, 0.0);
    EXPECT_GT(statistics.maximum, 50.0);
    EXPECT_LE(statistics.maximum, 100.0);
    std::int64_t clear = 0;
    field.cloudiness->forEachActive([&](const glm::i64vec3&, const float& value) {
        clear += value == 0.0f;
    });
    EXPECT_GT(clear, statistics.finiteCount / 4);
    EXPECT_LT(clear, statistics.finiteCount);
}

TEST(JetStream, isDeterministicPerSeedAndTime) {
    const JetStreamParameters parameters{{24, 16, 8}};
    const JetStreamField first = generateJetStream(parameters);
    const JetStreamField second = generateJetStream(parameters);
    EXPECT_EQ(values(first.cloudiness), values(second.cloudiness));
    EXPECT_EQ(dynamic_cast<const DenseVectorGrid&>(*first.wind).values(),
              dynamic_cast<const DenseVectorGrid&>(*second.wind).values());
    JetStreamParameters reseeded = parameters;
    reseeded.seed = 2;
    EXPECT_NE(values(generateJetStream(reseeded).cloudiness), values(first.cloudiness));
    JetStreamParameters later = parameters;
    later.time = 1.0;
    EXPECT_NE(values(magnitudeGrid(*generateJetStream(later).wind)),
              values(magnitudeGrid(*first.wind)));
}

TEST(JetStream, rejectsBadParameters) {
    JetStreamParameters reversed;
    reversed.latitudeMin = 60.0;
    reversed.latitudeMax = 20.0;
    try {
        generateJetStream(reversed);
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "jet-stream: latitude range must be finite and increasing, got 60 to 20");
    }
    JetStreamParameters flat;
    flat.dims = {8, 8, 0};
    try {
        generateJetStream(flat);
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "jet-stream: grid dimensions must be at least 1 voxel each, got 8 x 8 x 0");
    }
}

} // namespace
} // namespace texsplat::volume
