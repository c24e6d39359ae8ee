// A program's own data, rendered without a file (issue 12, "In memory, for embedding"):
// ExternalGrid reads the program's array in place, VolumeData::setGrid() draws it, framedScene()
// and sceneImage() frame and render a scene in one call; the same values from a file give the
// same image.
#include "nodes/volume/ExternalGrid.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/SceneImage.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

#ifdef TEXSPLAT_WITH_OPENVDB
#include "nodes/volume/VdbGrid.h"
#endif

#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

using test::errorOf;
using test::testPath;

constexpr int kSize = 12;

// kSize³ values, x fastest: a ball brighter towards its centre.
std::vector<float> ballValues() {
    std::vector<float> values;
    for (int z = 0; z < kSize; ++z)
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec3 offset = glm::vec3(x, y, z) - glm::vec3(0.5f * (kSize - 1));
                values.push_back(std::max(0.0f, 1.0f - glm::length(offset) / (0.5f * kSize)));
            }
    return values;
}

// The volume with a fixed transfer function (so both sides classify alike) and texture splats.
sg::Node::Ptr splatScene(const nodes::VolumeData::Ptr& data) {
    auto transfer = nodes::TransferFunction::create();
    transfer->opacities.setValue({0.0f, 4.0f});
    auto scene = sg::Separator::create();
    scene->addChild(data);
    scene->addChild(transfer);
    scene->addChild(nodes::TextureSplat::create());
    return scene;
}

image::Image render(const nodes::VolumeData::Ptr& data) {
    return render::sceneImage(splatScene(data), {64, 48, glm::vec4(0.0f), 1});
}

bool sameImage(const image::Image& a, const image::Image& b) {
    if (a.width() != b.width() || a.height() != b.height()) {
        return false;
    }
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (a.pixel(x, y) != b.pixel(x, y)) {
                return false;
            }
    return true;
}

float totalAlpha(const image::Image& image) {
    float sum = 0.0f;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            sum += image.pixel(x, y).a;
    return sum;
}

class InMemoryVolume : public ::testing::Test {
protected:
    void SetUp() override { nodes::registerNodeTypes(); }
};

TEST_F(InMemoryVolume, anExternalGridReadsTheProgramsValuesInPlace) {
    std::vector<float> values = ballValues();
    const volume::GridGeometry geometry({kSize, kSize, kSize}, glm::dvec3(0.0), glm::dvec3(0.5));
    const volume::ExternalScalarGrid grid(geometry, values.data(), values.size());
    EXPECT_EQ(grid.data(), values.data());
    const glm::i64vec3 centre(kSize / 2, kSize / 2, kSize / 2);
    EXPECT_FLOAT_EQ(grid.value(centre), values[grid.geometry().linearIndex(centre)]);
    values[grid.geometry().linearIndex(centre)] = 7.0f; // no copy: the grid sees the change
    EXPECT_FLOAT_EQ(grid.value(centre), 7.0f);
    values[0] = std::numeric_limits<float>::quiet_NaN(); // NaN: an empty voxel
    EXPECT_FALSE(grid.isActive({0, 0, 0}));
    EXPECT_FLOAT_EQ(grid.value({0, 0, 0}), 0.0f);
    std::size_t stored = 0;
    grid.forEachStored([&](const glm::i64vec3&, const float&) { ++stored; });
    EXPECT_EQ(stored, values.size());
    EXPECT_EQ(grid.memoryBytes(), values.size() * sizeof(float));
}

TEST_F(InMemoryVolume, anOwningGridKeepsTheMovedValuesWithoutACopy) {
    std::vector<float> values = ballValues();
    const float* buffer = values.data();
    const auto grid = volume::ExternalScalarGrid::owning(
        volume::GridGeometry({kSize, kSize, kSize}), std::move(values));
    EXPECT_EQ(grid->data(), buffer);
    EXPECT_GT(grid->value({kSize / 2, kSize / 2, kSize / 2}), 0.8f);
}

TEST_F(InMemoryVolume, aWrongValueCountOrANullPointerIsRefusedWithTheNumbers) {
    const std::vector<float> values(10, 1.0f);
    const volume::GridGeometry geometry({2, 3, 4});
    EXPECT_EQ(errorOf<DataError>([&] {
                  volume::ExternalScalarGrid(geometry, values.data(), values.size());
              }),
              "ExternalGrid: 10 values for a grid of 2 x 3 x 4 = 24 voxels");
    EXPECT_EQ(errorOf<DataError>([&] { volume::ExternalScalarGrid(geometry, nullptr, 24); }),
              "ExternalGrid: the values are a null pointer");
}

TEST_F(InMemoryVolume, rendersTheSameImageAsTheSameValuesReadFromAFile) {
    const std::vector<float> values = ballValues();
    const std::string path = testPath("ball.raw");
    {
        std::ofstream file(path, std::ios::binary);
        file.write(reinterpret_cast<const char*>(values.data()),
                   static_cast<std::streamsize>(values.size() * sizeof(float)));
    }
    auto fromFile = nodes::VolumeData::create();
    fromFile->source.setValue(nodes::VolumeSource::FileRawHeaderless);
    fromFile->fileName = path;
    fromFile->dimensions = glm::vec3(kSize);
    auto inMemory = nodes::VolumeData::create();
    inMemory->setGrid(std::make_shared<volume::ExternalScalarGrid>(
        volume::GridGeometry({kSize, kSize, kSize}), values.data(), values.size()));
    EXPECT_EQ(inMemory->source.as<nodes::VolumeSource>(), nodes::VolumeSource::Memory);
    const image::Image expected = render(fromFile);
    EXPECT_GT(totalAlpha(expected), 10.0f); // the ball shows
    EXPECT_TRUE(sameImage(render(inMemory), expected));
}

TEST_F(InMemoryVolume, changedValuesShowWithANewGridOverThem) {
    std::vector<float> values = ballValues();
    const volume::GridGeometry geometry({kSize, kSize, kSize});
    auto data = nodes::VolumeData::create();
    data->setGrid(
        std::make_shared<volume::ExternalScalarGrid>(geometry, values.data(), values.size()));
    const float before = totalAlpha(render(data));
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i % kSize < kSize / 2) {
            values[i] = 0.0f; // the ball's half at low x empty
        }
    }
    // The documented rule: a new grid over the changed values (no copy) is derived anew.
    data->setGrid(
        std::make_shared<volume::ExternalScalarGrid>(geometry, values.data(), values.size()));
    EXPECT_LT(totalAlpha(render(data)), 0.7f * before);
    data->setGrid(volume::ExternalScalarGrid::owning(geometry, ballValues()));
    EXPECT_FLOAT_EQ(totalAlpha(render(data)), before);
}

TEST_F(InMemoryVolume, aMemorySourceWithoutAGridSaysHowToGiveOne) {
    auto data = nodes::VolumeData::create();
    data->source.setValue(nodes::VolumeSource::Memory);
    const std::string message = errorOf<DataError>([&] { data->scalarGrid(); });
    EXPECT_NE(message.find("source MEMORY has no grid: a program gives it one with "
                           "VolumeData::setGrid(); a scene file cannot hold one"),
              std::string::npos)
        << message;
}

TEST_F(InMemoryVolume, framingAddsACameraOnlyWhereThereIsNoneAndNamesAnEmptyScene) {
    auto data = nodes::VolumeData::create();
    data->setGrid(volume::ExternalScalarGrid::owning(volume::GridGeometry({kSize, kSize, kSize}),
                                                       ballValues()));
    const sg::Node::Ptr scene = splatScene(data);
    const sg::Node::Ptr framed = render::framedScene(scene, 1.5f);
    ASSERT_NE(framed, scene);
    EXPECT_NE(render::findCamera(*framed), nullptr);
    EXPECT_EQ(render::framedScene(framed, 1.5f), framed); // it has a camera now
    render::Framing framing;
    framing.name = "my program's scene";
    EXPECT_EQ(errorOf<DataError>([&] { render::framedScene(sg::Separator::create(), 1.0f, framing); }),
              "my program's scene: nothing to frame (the scene has no geometry and no camera)");
    EXPECT_EQ(errorOf<DataError>([&] { render::sceneImage(scene, {0, 10}); }),
              "sceneImage(): the image must be at least 1 x 1 pixels, got 0 x 10");
}

#ifdef TEXSPLAT_WITH_OPENVDB
TEST_F(InMemoryVolume, anOpenVdbGridInMemoryRendersLikeTheSameValuesInAnArray) {
    openvdb::initialize();
    const std::vector<float> values = ballValues();
    auto vdb = openvdb::FloatGrid::create(0.0f);
    vdb->setName("ball");
    auto accessor = vdb->getAccessor();
    for (int z = 0; z < kSize; ++z)
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                accessor.setValue(openvdb::Coord(x, y, z), values[x + kSize * (y + kSize * z)]);
    auto fromVdb = nodes::VolumeData::create();
    fromVdb->setGrid(volume::gridFromVdb(*vdb));
    auto fromArray = nodes::VolumeData::create();
    fromArray->setGrid(std::make_shared<volume::ExternalScalarGrid>(
        volume::GridGeometry({kSize, kSize, kSize}), values.data(), values.size()));
    EXPECT_TRUE(sameImage(render(fromVdb), render(fromArray)));
}
#endif

} // namespace
} // namespace texsplat::nodes
