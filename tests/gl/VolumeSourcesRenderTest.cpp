// Every volume source, loaded and drawn through the scene nodes (camera, TransferFunction,
// VolumeData, TextureSplat; the GL backend): each gives a finite image with something in it,
// drawn as splats. Grids are small (at most 24³ voxels) so that llvmpipe draws each in a blink.

#include "SplatTestSupport.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/CameraView.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/GridStatistics.h"
#include "nodes/volume/RawVolume.h"
#include "scenegraph/Log.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

#ifdef TEXSPLAT_WITH_OPENVDB
#include <openvdb/openvdb.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

constexpr int kImageSize = 48;
// The most opaque pixel must be at least this opaque: the transfer function below makes the
// densest part of every volume optically thick, so anything less means nothing was drawn there.
constexpr double kMinimumPeakAlpha = 0.05;

// Opacity at the largest value: this many optical depths across the box's thinnest side.
constexpr float kOpticalDepth = 8.0f;

VolumeData::Ptr generated(VolumeSource source, const glm::vec3& resolution) {
    VolumeData::Ptr volume = VolumeData::create();
    volume->source.setValue(source);
    volume->resolution.setValue(resolution);
    return volume;
}

// Transparent at the grid's smallest value, rising linearly to kOpticalDepth over the box's
// thinnest side at its largest; viridis colours. Works for any source whatever its units.
TransferFunction::Ptr rampOver(const VolumeData& volume) {
    const volume::GridStatistics statistics = volume.scalarGrid()->statistics();
    const glm::vec3 side = volume.bounds().size();
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->preset.setValue(ColorPreset::Viridis);
    transfer->range.setValue(
        glm::vec2(static_cast<float>(statistics.minimum), static_cast<float>(statistics.maximum)));
    transfer->opacityValues.setValue({0.0f, 1.0f});
    transfer->opacities.setValue({0.0f, kOpticalDepth / std::min({side.x, side.y, side.z})});
    return transfer;
}

// Draws `volume` framed by an oblique perspective camera and checks the frame: splats drawn (at
// most one per voxel), every pixel finite with alpha in [0, 1], some pixel coloured and opaque.
void expectRenders(const VolumeData::Ptr& volume, const std::string& what) {
    SCOPED_TRACE(what);
    test::sharedContext();
    const volume::ScalarGridPtr grid = volume->scalarGrid();
    const volume::GridStatistics statistics = grid->statistics();
    ASSERT_LT(statistics.minimum, statistics.maximum) << "a constant grid cannot be classified";
    PerspectiveCamera::Ptr camera = PerspectiveCamera::create();
    camera->orientation.setValue(render::rotationLookingAlong(glm::vec3(-0.6f, -0.3f, -1.0f)));
    const sg::Separator::Ptr root =
        test::framedScene(camera, {rampOver(*volume), volume, TextureSplat::create()});

    const test::RenderedFrame frame = test::renderFrame(*root, kImageSize, kImageSize);
    EXPECT_GT(frame.statistics.splats, 0u);
    EXPECT_LE(frame.statistics.splats, static_cast<std::size_t>(statistics.finiteCount));
    test::expectFiniteWithAlphaInRange(frame.image, what);
    test::expectFiniteAndNotEmpty(frame.image, what);
    const double peakAlpha = frame.image.statistics().maximum.a;
    EXPECT_GT(peakAlpha, kMinimumPeakAlpha);
    ::testing::Test::RecordProperty(what + "_splats", std::to_string(frame.statistics.splats));
    ::testing::Test::RecordProperty(what + "_peak_alpha", std::to_string(peakAlpha));
}

// A ball of `size`³ voxels: 1 at the centre falling to 0 at the faces' midpoints.
double ball(int size, const glm::ivec3& index) {
    const glm::dvec3 centre(0.5 * (size - 1));
    return std::max(0.0, 1.0 - glm::length(glm::dvec3(index) - centre) / (0.5 * size));
}

// A swirl around the z axis of a `size`³ box with a constant updraft.
glm::vec3 swirl(int size, const glm::ivec3& index) {
    const glm::vec3 offset = glm::vec3(index) - glm::vec3(0.5f * static_cast<float>(size - 1));
    return glm::vec3(-offset.y, offset.x, 0.5f) / static_cast<float>(size);
}

TEST(VolumeSourcesRender, rawScalarAndVectorFilesRender) {
    constexpr int kSize = 12;
    volume::DenseGrid<float> scalars{volume::GridGeometry(glm::i64vec3(kSize))};
    volume::DenseGrid<glm::vec3> vectors{
        volume::GridGeometry(glm::i64vec3(kSize), glm::dvec3(-3.0), glm::dvec3(0.5))};
    for (int k = 0; k < kSize; ++k) {
        for (int j = 0; j < kSize; ++j) {
            for (int i = 0; i < kSize; ++i) {
                scalars.setValue({i, j, k}, static_cast<float>(ball(kSize, {i, j, k})));
                vectors.setValue({i, j, k}, swirl(kSize, {i, j, k}));
            }
        }
    }
    expectRenders(
        test::fileVolume(VolumeSource::FileRaw, test::writeTestVolume("sources_ball", scalars)),
        "raw_scalar");
    expectRenders(
        test::fileVolume(VolumeSource::FileRaw, test::writeTestVolume("sources_swirl", vectors)),
        "raw_vector_magnitude");
}

#ifdef TEXSPLAT_WITH_OPENVDB
// A file written with OpenVDB's own API: a float ball with one NaN voxel (which the reader
// treats as empty, with a warning) and a Vec3f swirl, both sparse, scaled and translated.
std::string writeVdbFile() {
    constexpr int kSize = 10;
    openvdb::initialize();
    openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    openvdb::Vec3fGrid::Ptr velocity = openvdb::Vec3fGrid::create(openvdb::Vec3f(0.0f));
    velocity->setName("velocity");
    openvdb::Mat4d matrix = openvdb::Mat4d::identity();
    matrix.preScale(openvdb::Vec3d(0.5, 0.5, 1.0));
    matrix.postTranslate(openvdb::Vec3d(2.0, -1.0, 3.0));
    velocity->setTransform(openvdb::math::Transform::createLinearTransform(matrix));
    openvdb::FloatGrid::Accessor densityAccessor = density->getAccessor();
    openvdb::Vec3fGrid::Accessor velocityAccessor = velocity->getAccessor();
    for (int k = 0; k < kSize; ++k) {
        for (int j = 0; j < kSize; ++j) {
            for (int i = 0; i < kSize; ++i) {
                const double value = ball(kSize, {i, j, k});
                if (value > 0.0) {
                    densityAccessor.setValue({i - 5, j + 7, k}, static_cast<float>(value));
                }
                const glm::vec3 v = swirl(kSize, {i, j, k});
                velocityAccessor.setValue({i, j, k}, openvdb::Vec3f(v.x, v.y, v.z));
            }
        }
    }
    densityAccessor.setValue({0, 12, 5}, std::numeric_limits<float>::quiet_NaN());
    const std::string path = ::testing::TempDir() + "texsplat_render_sources.vdb";
    openvdb::io::File(path).write({density, velocity});
    return path;
}

TEST(VolumeSourcesRender, openVdbFloatAndVec3fGridsRender) {
    const std::string path = writeVdbFile();
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&warnings](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning) {
            warnings.emplace_back(message);
        }
    });
    expectRenders(test::fileVolume(VolumeSource::FileVdb, path, "density"), "vdb_float");
    setLogSink(previous);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], path + ": grid 'density': 1 voxel is NaN or infinite; treated as empty");
    expectRenders(test::fileVolume(VolumeSource::FileVdb, path, "velocity"),
                  "vdb_vec3f_magnitude");
}
#endif

TEST(VolumeSourcesRender, everyGeneratorRenders) {
    expectRenders(generated(VolumeSource::Tornado, glm::vec3(16.0f)), "tornado");
    expectRenders(generated(VolumeSource::MarschnerLobb, glm::vec3(17.0f)), "marschner_lobb");
    expectRenders(generated(VolumeSource::Blob, glm::vec3(16.0f)), "blob");
    // Jet stream at a quarter of its default 96 x 48 x 24 samples: the wind magnitude (the
    // paper's figure 6) and the cloudiness scalar (figure 8).
    const glm::vec3 jetSamples(24.0f, 12.0f, 8.0f);
    expectRenders(generated(VolumeSource::JetStream, jetSamples), "jet_stream_wind");
    VolumeData::Ptr clouds = generated(VolumeSource::JetStream, jetSamples);
    clouds->component.setValue(VolumeComponent::Scalar);
    clouds->gridName.setValue("cloudiness");
    expectRenders(clouds, "jet_stream_cloudiness");
    expectRenders(generated(VolumeSource::Aerogel, glm::vec3(16.0f)), "aerogel");
}

} // namespace
} // namespace texsplat::nodes
