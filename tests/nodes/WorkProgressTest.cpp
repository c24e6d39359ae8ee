// Progress and cancel of a frame's long steps (issue 13): reading a volume file, classification
// and the octree build report to the action's work progress, which may cancel them; a cancelled
// step is started again by the next frame, and a cancelled load leaves nothing behind.
#include "nodes/volume/SparseGrid.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/Frame.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawVolume.h"
#include "scenegraph/Separator.h"
#include "scenegraph/WorkProgress.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#ifdef TEXSPLAT_WITH_OPENVDB
#include <openvdb/openvdb.h>
#endif

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace texsplat::nodes {
namespace {

// A ball in a 48³ box, drawn with a budget so that a frame classifies and builds an octree.
sg::Node::Ptr ballScene() {
    auto grid = std::make_shared<volume::SparseScalarGrid>(volume::GridGeometry(glm::i64vec3(48)));
    for (std::int64_t z = 0; z < 48; ++z)
        for (std::int64_t y = 0; y < 48; ++y)
            for (std::int64_t x = 0; x < 48; ++x) {
                const double r = glm::length(glm::dvec3(x, y, z) - glm::dvec3(24.0)) / 20.0;
                if (r < 1.0) {
                    grid->setValue(glm::i64vec3(x, y, z), static_cast<float>(1.0 - r));
                }
            }
    auto data = VolumeData::create();
    data->setGrid(volume::ScalarGridPtr(grid));
    auto transfer = TransferFunction::create();
    transfer->rangeMode.setValue(RangeMode::Fixed);
    auto splat = TextureSplat::create();
    splat->maxSplats.setValue(500);
    auto root = sg::Separator::create();
    root->addChild(data);
    root->addChild(transfer);
    root->addChild(splat);
    return render::framedScene(root, 1.0f);
}

class WorkProgressTest : public ::testing::Test {
protected:
    void SetUp() override { registerNodeTypes(); }
};

TEST_F(WorkProgressTest, classificationAndTheOctreeBuildReportFromZeroToOne) {
    const sg::Node::Ptr scene = ballScene();
    std::vector<std::pair<std::string, double>> reports;
    render::FrameAction action(16, 16);
    action.setWorkProgress([&reports](std::string_view step, double fraction) {
        reports.emplace_back(std::string(step), fraction);
        return true;
    });
    action.collect(*scene);
    ASSERT_GE(reports.size(), 4u);
    EXPECT_EQ(reports.front(), std::make_pair(std::string("classifying"), 0.0));
    EXPECT_EQ(reports.back(), std::make_pair(std::string("building the octree"), 1.0));
    for (std::size_t i = 1; i < reports.size(); ++i) {
        if (reports[i].first == reports[i - 1].first) {
            EXPECT_GE(reports[i].second, reports[i - 1].second) << i;
        }
    }
    reports.clear();
    action.collect(*scene);
    EXPECT_TRUE(reports.empty()) << "a frame that makes nothing new reports nothing";
}

TEST_F(WorkProgressTest, aCancelledStepThrowsAndTheNextFrameStartsItAgain) {
    for (const std::string cancelled : {"classifying", "building the octree"}) {
        SCOPED_TRACE(cancelled);
        const sg::Node::Ptr scene = ballScene();
        render::FrameAction action(16, 16);
        action.setWorkProgress([&cancelled](std::string_view step, double) {
            return step != cancelled;
        });
        try {
            action.collect(*scene);
            ADD_FAILURE() << "not cancelled";
        } catch (const sg::Cancelled& error) {
            EXPECT_NE(std::string(error.what()).find("TextureSplat: " + cancelled + ": cancelled"),
                      std::string::npos)
                << error.what();
        }
        action.setWorkProgress({});
        const render::Frame& frame = action.collect(*scene);
        ASSERT_EQ(frame.splats.size(), 1u);
        EXPECT_GT(frame.splats.front().splatCount(), 400u);
        EXPECT_EQ(action.statistics().builds.octrees, 1u);
        // Cancelling the octree build keeps the classification it was building on.
        EXPECT_EQ(action.statistics().builds.classifications,
                  cancelled == "classifying" ? 1u : 0u);
    }
}

// What a work progress was told, in order.
using Reports = std::vector<std::pair<std::string, double>>;

// A work progress that writes down what it is told and answers true.
sg::WorkProgress recorder(Reports& reports) {
    return [&reports](std::string_view step, double fraction) {
        reports.emplace_back(std::string(step), fraction);
        return true;
    };
}

// A work progress that answers false once `step` is `fraction` done.
sg::WorkProgress cancelling(const std::string& step, double fraction) {
    return [step, fraction](std::string_view told, double done) {
        return !(told == step && done >= fraction);
    };
}

// The fractions `reports` holds for `step`, in order.
std::vector<double> fractionsOf(const Reports& reports, const std::string& step) {
    std::vector<double> fractions;
    for (const auto& [told, fraction] : reports) {
        if (told == step) {
            fractions.push_back(fraction);
        }
    }
    return fractions;
}

// That `step` was told 0 first, then fractions that rise at least a percent at a time, and 1
// last (which may follow closer). Returns how many fractions it was told.
std::size_t expectRisingToOne(const Reports& reports, const std::string& step) {
    const std::vector<double> fractions = fractionsOf(reports, step);
    if (fractions.empty()) {
        ADD_FAILURE() << "no report of " << step;
        return 0;
    }
    EXPECT_EQ(fractions.front(), 0.0) << step;
    EXPECT_EQ(fractions.back(), 1.0) << step;
    for (std::size_t i = 1; i < fractions.size(); ++i) {
        EXPECT_GE(fractions[i], std::min(fractions[i - 1] + 0.01, 1.0)) << step << ", report " << i;
        EXPECT_GT(fractions[i], fractions[i - 1]) << step << ", report " << i;
    }
    return fractions.size();
}

// The step of reading the raw file `path`.
std::string readingStep(const std::string& path) {
    return "reading from " + std::filesystem::path(path).filename().string();
}

// A VolumeData reading the texsplat-raw file `path`.
VolumeData::Ptr rawFileNode(const std::string& path) {
    auto volume = VolumeData::create();
    volume->setName("big");
    volume->source.setValue(VolumeSource::FileRaw);
    volume->fileName = path;
    return volume;
}

// A value per voxel that differs from its neighbours.
float pattern(std::int64_t x, std::int64_t y, std::int64_t z) {
    return static_cast<float>((x * 7 + y * 13 + z * 29) % 101);
}

// 128 x 128 x 256 float32 voxels, 16 MiB: the raw reader reads it in four chunks of 4 MiB.
std::string writeBigRawFile(const std::string& path) {
    volume::DenseScalarGrid grid(volume::GridGeometry({128, 128, 256}));
    for (std::int64_t z = 0; z < 256; ++z)
        for (std::int64_t y = 0; y < 128; ++y)
            for (std::int64_t x = 0; x < 128; ++x)
                grid.setValue({x, y, z}, pattern(x, y, z));
    volume::writeRawVolume(path, grid);
    return path;
}

void expectSameGrid(const volume::ScalarGrid& read, const volume::ScalarGrid& expected) {
    ASSERT_EQ(read.geometry(), expected.geometry());
    const glm::i64vec3 dims = read.geometry().dims();
    std::int64_t different = 0;
    for (std::int64_t z = 0; z < dims.z; ++z)
        for (std::int64_t y = 0; y < dims.y; ++y)
            for (std::int64_t x = 0; x < dims.x; ++x)
                different += read.value({x, y, z}) != expected.value({x, y, z}) ? 1 : 0;
    EXPECT_EQ(different, 0);
}

TEST_F(WorkProgressTest, framingAndAFrameReportReadingTheFileBeforeClassifying) {
    const auto scene = [](const std::string& path, bool withCamera) {
        volume::DenseScalarGrid grid(volume::GridGeometry({4, 4, 4}));
        grid.setValue({1, 2, 3}, 1.0f);
        volume::writeRawVolume(path, grid);
        auto root = sg::Separator::create();
        if (withCamera) {
            root->addChild(PerspectiveCamera::create());
        }
        root->addChild(rawFileNode(path));
        root->addChild(TransferFunction::create());
        root->addChild(TextureSplat::create());
        return root;
    };
    const auto expected = [](const std::string& path) {
        return Reports{{readingStep(path), 0.0}, {readingStep(path), 1.0}};
    };

    // A scene without a camera is framed, which reads its volumes.
    const std::string framedFile = test::testPath("framed.raw");
    Reports reports;
    render::Framing framing;
    framing.progress = recorder(reports);
    const sg::Node::Ptr framed = render::framedScene(scene(framedFile, false), 1.0f, framing);
    EXPECT_EQ(reports, expected(framedFile));
    reports.clear();
    render::FrameAction action(16, 16);
    action.setWorkProgress(recorder(reports));
    action.collect(*framed);
    EXPECT_TRUE(fractionsOf(reports, readingStep(framedFile)).empty()) << "loaded already";

    // In a scene with a camera, the splat node reads it first.
    const std::string cameraFile = test::testPath("camera.raw");
    reports.clear();
    action.collect(*scene(cameraFile, true));
    ASSERT_GE(reports.size(), 3u);
    EXPECT_EQ(Reports(reports.begin(), reports.begin() + 2), expected(cameraFile));
    EXPECT_EQ(reports[2].first, "classifying");
}

TEST_F(WorkProgressTest, aRawFileReportsTheFractionReadAndACancelledLoadKeepsNothing) {
    const std::string path = writeBigRawFile(test::testPath("big.raw"));
    const std::string step = readingStep(path);
    const auto expected = std::get<volume::ScalarGridPtr>(volume::readRawVolume(path));

    const VolumeData::Ptr volume = rawFileNode(path);
    EXPECT_EQ(test::errorOf<sg::Cancelled>([&] { volume->load(cancelling(step, 0.3)); }),
              "VolumeData 'big': " + step + ": cancelled");
    EXPECT_FALSE(volume->isLoaded());

    Reports reports;
    volume->load(recorder(reports));
    EXPECT_EQ(expectRisingToOne(reports, step), 5u); // 0, then one per 4 MiB chunk
    EXPECT_TRUE(volume->isLoaded());
    expectSameGrid(*volume->scalarGrid(), *expected);
}

TEST_F(WorkProgressTest, aLoadThatOneNodeCancelsLeavesTheSharedGridToLoadForTheOther) {
    const std::string path = writeBigRawFile(test::testPath("shared.raw"));
    const std::string step = readingStep(path);
    const VolumeData::Ptr first = rawFileNode(path);
    const VolumeData::Ptr second = rawFileNode(path);
    EXPECT_THROW(first->load(cancelling(step, 0.3)), sg::Cancelled);

    Reports reports;
    second->load(recorder(reports));
    EXPECT_EQ(expectRisingToOne(reports, step), 5u);
    // The first node now shares the second's grid, without reading.
    reports.clear();
    first->load(recorder(reports));
    EXPECT_TRUE(reports.empty());
    EXPECT_EQ(first->scalarGrid(), second->scalarGrid());
}

#ifdef TEXSPLAT_WITH_OPENVDB
TEST_F(WorkProgressTest, aVdbFileReportsTheBytesOpenVdbReadsAndACancelledLoadKeepsNothing) {
    // 128^3 voxels of values that do not compress: about 8 MiB of the file is the grid's.
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    auto accessor = density->getAccessor();
    std::uint32_t random = 1;
    const auto valueAt = [](std::uint32_t state) { return static_cast<float>(state >> 8) + 1.0f; };
    for (int z = 0; z < 128; ++z)
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) {
                random = random * 1664525u + 1013904223u;
                accessor.setValue({x, y, z}, valueAt(random));
            }
    auto other = openvdb::FloatGrid::create(0.0f);
    other->setName("other");
    other->getAccessor().setValue({0, 0, 0}, 1.0f);
    const std::string path = test::testPath("big.vdb");
    openvdb::io::File(path).write({other, density}); // a grid before it is skipped
    const std::string file = std::filesystem::path(path).filename().string();
    const std::string reading = "reading grid 'density' from " + file;

    auto volume = VolumeData::create();
    volume->setName("cloud");
    volume->source.setValue(VolumeSource::FileVdb);
    volume->fileName = path;
    volume->gridName = "density";
    EXPECT_EQ(test::errorOf<sg::Cancelled>([&] { volume->load(cancelling(reading, 0.3)); }),
              "VolumeData 'cloud': " + reading + ": cancelled");
    EXPECT_FALSE(volume->isLoaded());

    Reports reports;
    volume->load(recorder(reports));
    EXPECT_GE(expectRisingToOne(reports, reading), 9u); // 0, one per MiB read, 1
    EXPECT_GE(expectRisingToOne(reports, "copying grid 'density' from " + file), 2u);
    const volume::ScalarGridPtr grid = volume->scalarGrid();
    ASSERT_EQ(grid->geometry().dims(), glm::i64vec3(128));
    random = 1;
    std::int64_t different = 0;
    for (int z = 0; z < 128; ++z)
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) {
                random = random * 1664525u + 1013904223u;
                different += grid->value({x, y, z}) != valueAt(random) ? 1 : 0;
            }
    EXPECT_EQ(different, 0);
}
#endif

} // namespace
} // namespace texsplat::nodes
