#include "nodes/VolumeData.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/Transform.h"
#include "nodes/elements/VolumeElement.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawVolume.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#ifdef TEXSPLAT_WITH_OPENVDB
#include <openvdb/openvdb.h>
#endif

#include <chrono>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace texsplat::nodes {
namespace {

using test::errorOf;
using test::testPath;

// Collects the Info messages logged while it lives.
class InfoLog {
public:
    InfoLog()
        : mPrevious(setLogSink([this](LogLevel level, std::string_view message) {
              if (level == LogLevel::Info)
                  mMessages.emplace_back(message);
          })) {}
    ~InfoLog() { setLogSink(mPrevious); }
    InfoLog(const InfoLog&) = delete;
    InfoLog& operator=(const InfoLog&) = delete;

    const std::vector<std::string>& messages() const { return mMessages; }

private:
    std::vector<std::string> mMessages;
    LogSink mPrevious;
};

VolumeData::Ptr generated(VolumeSource source, float samples) {
    const auto volume = VolumeData::create();
    volume->source.setValue(source);
    volume->resolution = glm::vec3(samples);
    return volume;
}

TEST(VolumeData, loadsOnlyWhenUsed) {
    const auto volume = generated(VolumeSource::Blob, 8.0f);
    EXPECT_FALSE(volume->isLoaded());
    const volume::ScalarGridPtr grid = volume->scalarGrid();
    EXPECT_TRUE(volume->isLoaded());
    EXPECT_EQ(grid->geometry().dims(), glm::i64vec3(8));
    EXPECT_EQ(volume->scalarGrid(), grid); // cached
    EXPECT_EQ(volume->vectorGrid(), nullptr);
}

TEST(VolumeData, reloadsWhenAFieldChanges) {
    const auto volume = generated(VolumeSource::Blob, 8.0f);
    const volume::ScalarGridPtr first = volume->scalarGrid();
    volume->resolution = glm::vec3(4.0f, 5.0f, 6.0f);
    EXPECT_FALSE(volume->isLoaded());
    const volume::ScalarGridPtr second = volume->scalarGrid();
    EXPECT_NE(second, first);
    EXPECT_EQ(second->geometry().dims(), glm::i64vec3(4, 5, 6));
    EXPECT_EQ(first->geometry().dims(), glm::i64vec3(8)); // users of the old grid keep it
}

TEST(VolumeData, tornadoGivesVectorsAndTheirMagnitude) {
    const auto volume = generated(VolumeSource::Tornado, 6.0f);
    const volume::VectorGridPtr vectors = volume->vectorGrid();
    ASSERT_NE(vectors, nullptr);
    const volume::ScalarGridPtr magnitude = volume->scalarGrid();
    const glm::i64vec3 index(1, 2, 3);
    EXPECT_FLOAT_EQ(magnitude->value(index), glm::length(vectors->value(index)));
    // The funnel moves with time: a new time gives other vectors.
    volume->time = 50.0f;
    EXPECT_NE(volume->vectorGrid()->value(index), vectors->value(index));
}

TEST(VolumeData, generatesTheScalarSources) {
    const auto lobb = generated(VolumeSource::MarschnerLobb, 5.0f);
    const volume::ScalarGridPtr signal = lobb->scalarGrid();
    // At the origin (the middle sample on [-1,1]^3): (1 + 2 alpha) / (2 (1 + alpha)) = 0.6.
    EXPECT_NEAR(signal->value({2, 2, 2}), 0.6f, 1e-6f);
    const auto blob = generated(VolumeSource::Blob, 5.0f);
    EXPECT_GT(blob->scalarGrid()->value({2, 2, 2}), 0.0f);
    EXPECT_EQ(blob->vectorGrid(), nullptr);
}

TEST(VolumeData, jetStreamOffersCloudinessAsItsScalar) {
    const auto volume = generated(VolumeSource::JetStream, 6.0f);
    ASSERT_NE(volume->vectorGrid(), nullptr);
    volume->component.setValue(VolumeComponent::Scalar);
    volume->gridName = "cloudiness";
    const volume::ScalarGridPtr clouds = volume->scalarGrid();
    const volume::GridStatistics statistics = clouds->statistics();
    EXPECT_GE(statistics.minimum, 0.0);
    EXPECT_LE(statistics.maximum, 100.0);
    EXPECT_EQ(clouds->geometry(), volume->vectorGrid()->geometry());
}

TEST(VolumeData, aerogelHasFibers) {
    const auto volume = generated(VolumeSource::Aerogel, 6.0f);
    EXPECT_EQ(volume->fibers().size(), 24u);
    EXPECT_NE(volume->vectorGrid(), nullptr);
    EXPECT_TRUE(generated(VolumeSource::Blob, 4.0f)->fibers().empty());
}

TEST(VolumeData, readsARawFile) {
    volume::DenseScalarGrid grid(volume::GridGeometry({2, 3, 4}, {1.0, 2.0, 3.0}, {0.5, 0.5, 1.0}));
    grid.setValue({1, 2, 3}, 42.0f);
    const std::string path = testPath("grid.raw");
    volume::writeRawVolume(path, grid);
    const auto volume = VolumeData::create();
    volume->source.setValue(VolumeSource::FileRaw);
    volume->fileName = path;
    const InfoLog log;
    const volume::ScalarGridPtr read = volume->scalarGrid();
    EXPECT_EQ(read->geometry(), grid.geometry());
    EXPECT_EQ(read->value({1, 2, 3}), 42.0f);
    EXPECT_TRUE(log.messages().empty()) << "a small file loads quietly";
}

TEST(VolumeData, nodesReadingTheSameFileShareOneGridWhileOneHoldsIt) {
    volume::DenseScalarGrid grid(volume::GridGeometry({2, 3, 4}));
    grid.setValue({1, 2, 3}, 42.0f);
    const std::string path = testPath("shared.raw");
    volume::writeRawVolume(path, grid);
    const auto reader = [&path] {
        const auto volume = VolumeData::create();
        volume->source.setValue(VolumeSource::FileRaw);
        volume->fileName = path;
        return volume;
    };
    auto first = reader();
    const auto second = reader();
    volume::ScalarGridPtr read = first->scalarGrid();
    EXPECT_EQ(second->scalarGrid(), read);
    const std::weak_ptr<const volume::ScalarGrid> released = read;
    read.reset();

    // Nothing else holds the grid once both nodes let it go; a changed file is read again.
    first.reset();
    second->fileName = path; // a field change drops the node's load
    grid.setValue({1, 2, 3}, 7.0f);
    volume::writeRawVolume(path, grid);
    std::filesystem::last_write_time(path, std::filesystem::last_write_time(path) +
                                               std::chrono::seconds(1));
    const volume::ScalarGridPtr reread = second->scalarGrid();
    EXPECT_TRUE(released.expired());
    EXPECT_EQ(reread->value({1, 2, 3}), 7.0f);
}

TEST(VolumeData, logsTheProgressOfABigFile) {
    // 256^3 float32 = 64 MiB, the size from which progress is logged: a file of zeros, sparse on
    // disk, read in 16 chunks of 4 MiB.
    const std::string path = testPath("big.raw");
    {
        std::ofstream(path, std::ios::binary) << "texsplat-raw 1\ndims 256 256 256\ntype float32\n"
                                                 "data\n";
    }
    std::filesystem::resize_file(path, std::filesystem::file_size(path) +
                                           volume::kLogProgressFileBytes);
    const auto volume = VolumeData::create();
    volume->setName("big");
    volume->source.setValue(VolumeSource::FileRaw);
    volume->fileName = path;
    std::vector<std::string> expected;
    for (const char* step : {"", " 12%", " 25%", " 31%", " 43%", " 50%", " 62%", " 75%", " 81%",
                             " 93%", " 100%"})
        expected.push_back("VolumeData 'big': " + path + ": reading" + step);
    {
        const InfoLog log;
        EXPECT_EQ(volume->scalarGrid()->geometry().dims(), glm::i64vec3(256));
        EXPECT_EQ(log.messages(), expected);
    }
    std::filesystem::remove(path);
}

TEST(VolumeData, progressOfSmallFilesIsLoggedOnlyOnceTheLoadIsSlow) {
    const InfoLog log;
    volume::ProgressCallback progress = volume::logProgress("slow.vdb", 1000);
    EXPECT_TRUE(progress(0.0, "reading grid 'fog'"));
    std::this_thread::sleep_for(std::chrono::duration<double>(volume::kLogProgressDelaySeconds));
    EXPECT_TRUE(progress(0.42, "copying grid 'fog'"));
    EXPECT_TRUE(progress(0.45, "copying grid 'fog'"));
    EXPECT_TRUE(progress(0.5, "copying grid 'fog'"));
    EXPECT_EQ(log.messages(),
              (std::vector<std::string>{"slow.vdb: copying grid 'fog' 42%",
                                        "slow.vdb: copying grid 'fog' 50%"}));
}

#ifdef TEXSPLAT_WITH_OPENVDB
TEST(VolumeData, readsAGridOfAnOpenVdbFile) {
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->getAccessor().setValue({3, 4, 5}, 2.5f);
    const std::string path = testPath("cloud.vdb");
    openvdb::io::File(path).write({density});
    const auto volume = VolumeData::create();
    volume->setName("cloud");
    volume->source.setValue(VolumeSource::FileVdb);
    volume->fileName = path;
    volume->gridName = "density";
    const volume::ScalarGridPtr grid = volume->scalarGrid();
    EXPECT_EQ(grid->geometry().dims(), glm::i64vec3(1));
    EXPECT_EQ(grid->value({0, 0, 0}), 2.5f);
}

TEST(VolumeData, aFileOfOneGridNeedsNoGridNameAndOtherwiseTheGridsAreListed) {
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->getAccessor().setValue({3, 4, 5}, 2.5f);
    const std::string one = testPath("one.vdb");
    openvdb::io::File(one).write({density});
    const auto volume = VolumeData::create();
    volume->setName("cloud");
    volume->source.setValue(VolumeSource::FileVdb);
    volume->fileName = one;
    EXPECT_EQ(volume->scalarGrid()->value({0, 0, 0}), 2.5f);

    auto velocity = openvdb::Vec3SGrid::create();
    velocity->setName("velocity");
    velocity->getAccessor().setValue({0, 0, 0}, openvdb::Vec3s(1.0f, 0.0f, 0.0f));
    const std::string two = testPath("two.vdb");
    openvdb::io::File(two).write({density, velocity});
    volume->fileName = two;
    EXPECT_EQ(errorOf<DataError>([&] { volume->scalarGrid(); }),
              "VolumeData 'cloud': gridName is empty and " + two +
                  " has 2 grids; set gridName to one of: density (float), velocity (vec3s)");
    volume->gridName = "pressure";
    EXPECT_EQ(errorOf<DataError>([&] { volume->scalarGrid(); }),
              "VolumeData 'cloud': " + two +
                  ": no grid named 'pressure'; the file has: density (float), velocity (vec3s)");
    volume->gridName = "velocity";
    EXPECT_EQ(volume->vectorGrid()->value({0, 0, 0}), glm::vec3(1.0f, 0.0f, 0.0f));

    const std::string none = testPath("none.vdb");
    openvdb::io::File(none).write(openvdb::GridCPtrVec());
    volume->fileName = none;
    volume->gridName = "";
    EXPECT_EQ(errorOf<DataError>([&] { volume->scalarGrid(); }),
              "VolumeData 'cloud': " + none + ": the file has no grids");
}
#endif

// Restores the working directory when it goes out of scope.
class WorkingDirectory {
public:
    explicit WorkingDirectory(const std::filesystem::path& directory)
        : mPrevious(std::filesystem::current_path()) {
        std::filesystem::current_path(directory);
    }
    ~WorkingDirectory() { std::filesystem::current_path(mPrevious); }
    WorkingDirectory(const WorkingDirectory&) = delete;
    WorkingDirectory& operator=(const WorkingDirectory&) = delete;

private:
    std::filesystem::path mPrevious;
};

// A folder of its own for the test, made empty.
std::filesystem::path testFolder(const std::string& name) {
    const std::filesystem::path folder = testPath(name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

TEST(VolumeData, relativeFileNamesResolveAgainstTheSceneFilesFolder) {
    registerNodeTypes();
    const std::filesystem::path project = testFolder("project");
    std::filesystem::create_directories(project / "scenes" / "data");
    std::filesystem::create_directories(project / "elsewhere");
    volume::DenseScalarGrid grid(volume::GridGeometry({2, 3, 4}, {0.0, 0.0, 0.0}, {1, 1, 1}), 1.0f);
    volume::writeRawVolume((project / "scenes" / "data" / "grid.raw").string(), grid);
    const std::string text = "#Inventor V2.1 ascii\n"
                             "DEF cloud VolumeData { source FILE_RAW fileName \"data/grid.raw\" "
                             "}\n";
    std::ofstream(project / "scenes" / "scene.iv") << text;

    const WorkingDirectory elsewhere(project / "elsewhere");
    const sg::Node::Ptr root = sg::SceneReader::readFile("../scenes/scene.iv");
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox().min(), glm::vec3(-0.5f));
    EXPECT_EQ(action.boundingBox().max(), glm::vec3(1.5f, 2.5f, 3.5f));
    // The field keeps the name as written, so the scene written back still travels with its data.
    const auto& volume = static_cast<const VolumeData&>(*root);
    EXPECT_EQ(volume.fileName.value(), "data/grid.raw");
    EXPECT_EQ(volume.baseDirectory(), (project / "elsewhere" / ".." / "scenes").string());

    // An absolute name is used as it is.
    const sg::Node::Ptr absolute = sg::SceneReader::readString(
        "#Inventor V2.1 ascii\nVolumeData { source FILE_RAW fileName \"" +
        (project / "scenes" / "data" / "grid.raw").string() + "\" }\n");
    EXPECT_EQ(static_cast<const VolumeData&>(*absolute).bounds().max(),
              glm::vec3(1.5f, 2.5f, 3.5f));
}

TEST(VolumeData, aMissingFileIsNamedByTheFullPathTried) {
    registerNodeTypes();
    const std::filesystem::path folder = testFolder("scenes");
    std::ofstream(folder / "scene.iv")
        << "#Inventor V2.1 ascii\n"
           "DEF cloud VolumeData { source FILE_NPY fileName \"cloud.npy\" }\n";
    const WorkingDirectory elsewhere(::testing::TempDir());
    const sg::Node::Ptr root = sg::SceneReader::readFile((folder / "scene.iv").string());
    const auto& volume = static_cast<const VolumeData&>(*root);
    EXPECT_EQ(errorOf<IoError>([&] { volume.bounds(); }),
              "VolumeData 'cloud': " + (folder / "cloud.npy").string() +
                  ": cannot open file (No such file or directory)");
}

TEST(VolumeData, aNodeMadeInCodeResolvesAgainstTheWorkingDirectory) {
    const std::filesystem::path folder = testFolder("code");
    volume::DenseScalarGrid grid(volume::GridGeometry({2, 2, 2}), 3.0f);
    volume::writeRawVolume((folder / "grid.raw").string(), grid);
    const WorkingDirectory inFolder(folder);
    const auto volume = VolumeData::create();
    volume->source.setValue(VolumeSource::FileRaw);
    volume->fileName = "grid.raw";
    EXPECT_EQ(volume->baseDirectory(), "");
    EXPECT_EQ(volume->scalarGrid()->value({1, 1, 1}), 3.0f);
}

TEST(VolumeData, readsAHeaderlessRawFileAsTheSceneDescribesIt) {
    registerNodeTypes();
    const std::filesystem::path folder = testFolder("headerless");
    {
        std::ofstream out(folder / "ct.raw", std::ios::binary);
        out << "HEAD";
        // 3 x 2 x 1 voxels of big-endian int16: 256 * i - 1.
        for (int i = 0; i < 6; ++i) {
            const auto value = static_cast<std::uint16_t>(static_cast<std::int16_t>(256 * i - 1));
            out.put(static_cast<char>(value >> 8)).put(static_cast<char>(value & 0xff));
        }
    }
    std::ofstream(folder / "scene.iv")
        << "#Inventor V2.1 ascii\nDEF ct VolumeData { source FILE_RAW_HEADERLESS fileName "
           "\"ct.raw\" dimensions 3 2 1 dataType INT16 byteOrder BIG headerBytes 4 }\n";
    const sg::Node::Ptr root = sg::SceneReader::readFile((folder / "scene.iv").string());
    auto& volume = static_cast<VolumeData&>(*root);
    const volume::ScalarGridPtr grid = volume.scalarGrid();
    EXPECT_EQ(grid->geometry().dims(), glm::i64vec3(3, 2, 1));
    EXPECT_EQ(grid->value({0, 0, 0}), -1.0f);
    EXPECT_EQ(grid->value({2, 1, 0}), 1279.0f);

    const std::string path = (folder / "ct.raw").string();
    volume.headerBytes = 0;
    EXPECT_EQ(errorOf<DataError>([&] { volume.scalarGrid(); }),
              "VolumeData 'ct': " + path + ": file size mismatch: the scene describes 3 x 2 x 1 "
              "voxels x 1 component x 2 bytes (int16) = 12 bytes, plus 0 header bytes = 12 bytes, "
              "but the file has 16 bytes");
    volume.dimensions = glm::vec3(3.0f, 0.0f, 1.0f);
    EXPECT_EQ(errorOf<DataError>([&] { volume.scalarGrid(); }),
              "VolumeData 'ct': dimensions must hold whole numbers from 1 to 1e9, got 3 0 1");
    volume.dimensions = glm::vec3(1.0f);
    volume.components = 2;
    EXPECT_EQ(errorOf<DataError>([&] { volume.scalarGrid(); }),
              "VolumeData 'ct': components must be 1 or 3, got 2");
    volume.components = 1;
    volume.headerBytes = -4;
    EXPECT_EQ(errorOf<DataError>([&] { volume.scalarGrid(); }),
              "VolumeData 'ct': headerBytes must be 0 or more, got -4");

    // The same file as FILE_RAW: the format expected is named and no byte of it printed.
    volume.source.setValue(VolumeSource::FileRaw);
    EXPECT_EQ(errorOf<ParseError>([&] { volume.scalarGrid(); }),
              "VolumeData 'ct': " + path + ":1:1: expected 'texsplat-raw 1' on the first line, "
              "found binary data (a headerless raw file? give its layout: texsplat info FILE "
              "--dims X,Y,Z --type TYPE, or in a scene VolumeData source FILE_RAW_HEADERLESS)");
}

TEST(VolumeData, readsANumpyFile) {
    const std::string path = testPath("grid.npy");
    {
        std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 1, 3), }";
        header.resize(128 - 10 - 1, ' ');
        header += '\n';
        std::ofstream out(path, std::ios::binary);
        out << std::string("\x93NUMPY\x01\x00", 8) << char(header.size()) << '\0' << header;
        for (int i = 0; i < 6; ++i) {
            const float value = 0.5f * float(i);
            out.write(reinterpret_cast<const char*>(&value), sizeof value);
        }
    }
    const auto volume = VolumeData::create();
    volume->source.setValue(VolumeSource::FileNpy);
    volume->fileName = path;
    const volume::ScalarGridPtr grid = volume->scalarGrid();
    EXPECT_EQ(grid->geometry().dims(), glm::i64vec3(3, 1, 2));
    EXPECT_EQ(grid->value({2, 0, 0}), 1.0f);
    EXPECT_EQ(grid->value({0, 0, 1}), 1.5f);
}

// `origin` and `spacing` place any source's voxels (winds from a .npy over clouds from a NetCDF
// file): the same voxels, read through, not copied; the box and both grids follow.
TEST(VolumeData, originAndSpacingPlaceAnySourcesVoxels) {
    const auto tornado = generated(VolumeSource::Tornado, 4.0f);
    const volume::VectorGridPtr own = tornado->vectorGrid();
    tornado->origin.setValue({glm::vec3(-140.0f, 15.0f, 0.0f)});
    tornado->spacing.setValue({glm::vec3(2.0f, 1.0f, 0.5f)});
    const volume::VectorGridPtr placed = tornado->vectorGrid();
    EXPECT_EQ(placed->geometry(),
              volume::GridGeometry({4, 4, 4}, {-140.0, 15.0, 0.0}, {2.0, 1.0, 0.5}));
    EXPECT_EQ(placed->value({1, 2, 3}), own->value({1, 2, 3}));
    EXPECT_EQ(tornado->vectorGrid(), placed) << "made once per load: caches key on it";
    EXPECT_EQ(tornado->scalarGrid()->geometry(), placed->geometry());
    EXPECT_EQ(tornado->scalarGrid()->value({1, 2, 3}), glm::length(own->value({1, 2, 3})));
    const sg::Box3 box = tornado->bounds();
    EXPECT_EQ(box.min(), glm::vec3(-141.0f, 14.5f, -0.25f));
    EXPECT_EQ(box.max(), glm::vec3(-133.0f, 18.5f, 1.75f));
    // One of the two: the other stays the source's own.
    tornado->origin.setValue({});
    EXPECT_EQ(tornado->scalarGrid()->geometry().origin(), own->geometry().origin());
    EXPECT_EQ(tornado->scalarGrid()->geometry().spacing(), glm::dvec3(2.0, 1.0, 0.5));

    tornado->spacing.setValue({glm::vec3(1.0f, 0.0f, 1.0f)});
    EXPECT_EQ(errorOf<DataError>([&] { tornado->scalarGrid(); }),
              "VolumeData: origin and spacing: grid spacing must be finite and positive, got 1 0 "
              "1");
    tornado->spacing.setValue({glm::vec3(1.0f), glm::vec3(2.0f)});
    EXPECT_EQ(errorOf<DataError>([&] { tornado->vectorGrid(); }),
              "VolumeData: spacing holds one x y z (or none, for the source's own), got 2 "
              "values");
}

TEST(VolumeData, errorsNameTheNodeAndTheSource) {
    const auto volume = VolumeData::create();
    volume->setName("cloud");
    volume->source.setValue(VolumeSource::FileRaw);
    EXPECT_EQ(errorOf<DataError>([&] { volume->scalarGrid(); }),
              "VolumeData 'cloud': fileName is empty; source FILE_RAW reads a file");
    const std::string missing = testPath("missing.raw");
    volume->fileName = missing;
    EXPECT_EQ(errorOf<IoError>([&] { volume->scalarGrid(); }),
              "VolumeData 'cloud': " + missing + ": cannot open file (No such file or directory)");
    EXPECT_FALSE(volume->isLoaded());

    volume->source.setValue(VolumeSource::Blob);
    volume->resolution = glm::vec3(4.0f, 0.0f, 4.5f);
    EXPECT_EQ(errorOf<DataError>([&] { volume->bounds(); }),
              "VolumeData 'cloud': resolution must hold whole numbers from 1 to 1e9, got 4 0 4.5");

    volume->source.setValue(VolumeSource::Tornado);
    volume->resolution = glm::vec3(4.0f);
    volume->component.setValue(VolumeComponent::Scalar);
    EXPECT_EQ(errorOf<DataError>([&] { volume->scalarGrid(); }),
              "VolumeData 'cloud': component SCALAR: source TORNADO has no scalar grid '' (it has "
              "vectors only; use MAGNITUDE)");
    volume->source.setValue(VolumeSource::JetStream);
    volume->gridName = "rain";
    EXPECT_EQ(errorOf<DataError>([&] { volume->scalarGrid(); }),
              "VolumeData 'cloud': component SCALAR: source JET_STREAM has no scalar grid 'rain' "
              "(it has: cloudiness)");

    volume->time = std::nanf("");
    EXPECT_EQ(errorOf<DataError>([&] { volume->vectorGrid(); }).rfind("VolumeData 'cloud': ", 0),
              0u);
}

TEST(VolumeData, boundingBoxIsTheGridBoundsUnderTheModelMatrix) {
    // BLOB samples [-1,1]^3; 5 samples: spacing 0.5, cells reach 0.25 beyond the ends.
    const auto volume = generated(VolumeSource::Blob, 5.0f);
    EXPECT_EQ(volume->bounds(), sg::Box3(glm::vec3(-1.25f), glm::vec3(1.25f)));
    const auto root = sg::Separator::create();
    const auto transform = Transform::create();
    transform->translation = glm::vec3(10.0f, 0.0f, 0.0f);
    root->addChild(transform);
    root->addChild(volume);
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(),
              sg::Box3(glm::vec3(8.75f, -1.25f, -1.25f), glm::vec3(11.25f, 1.25f, 1.25f)));
}

TEST(VolumeData, putsItselfIntoTheStateWithoutLoading) {
    const auto root = sg::Separator::create();
    const auto volume = generated(VolumeSource::Blob, 4.0f);
    const auto probe = test::StateProbe::create();
    const VolumeData* seen = nullptr;
    probe->visit = [&](sg::Action& action) { seen = action.state().get<VolumeElement>().volume; };
    root->addChild(volume);
    root->addChild(probe);
    sg::SearchAction search; // visits every node, computes nothing
    search.setName("nothingIsCalledThis");
    search.apply(*root);
    EXPECT_EQ(seen, volume.get());
    EXPECT_FALSE(volume->isLoaded());
}

} // namespace
} // namespace texsplat::nodes
