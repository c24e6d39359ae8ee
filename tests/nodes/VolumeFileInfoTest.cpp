#include "nodes/volume/VolumeFileInfo.h"

#include "SceneNodesTestSupport.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#ifdef TEXSPLAT_WITH_OPENVDB
#include <openvdb/openvdb.h>
#endif

#include <filesystem>
#include <fstream>
#include <string>

namespace texsplat::volume {
namespace {

using texsplat::nodes::test::testPath;

TEST(VolumeFileInfo, detectsTheFormatByItsFirstBytesThenItsExtension) {
    const auto write = [](const std::string& path, const std::string& bytes) {
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    };
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("a.dat"), "texsplat-raw 1\n")),
              VolumeFileFormat::TexsplatRaw);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("a.dat"), std::string("\x93NUMPY\x01\x00", 8))),
              VolumeFileFormat::Npy);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("a.dat"), std::string(" BDV\0\0\0\0", 8))),
              VolumeFileFormat::Vdb);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("a.dat"), "NRRD0004\n")),
              VolumeFileFormat::Nrrd);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("a.dat"), std::string("CDF\x01", 4))),
              VolumeFileFormat::NetCdf);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("a.dat"), "\x89HDF\r\n\x1a\n")),
              VolumeFileFormat::NetCdf);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("b.nhdr"), "junk")), VolumeFileFormat::Nrrd);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("b.nc"), "junk")), VolumeFileFormat::NetCdf);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("b.raw"), "junk")),
              VolumeFileFormat::TexsplatRaw);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("b.npy"), "junk")), VolumeFileFormat::Npy);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("b.vdb"), "junk")), VolumeFileFormat::Vdb);
    EXPECT_EQ(detectVolumeFileFormat(write(testPath("scene.iv"), "#Inventor V2.1 ascii\n")),
              VolumeFileFormat::Unknown);
    EXPECT_EQ(detectVolumeFileFormat(testPath("missing.npy")), VolumeFileFormat::Unknown);
    EXPECT_EQ(detectVolumeFileFormat(::testing::TempDir()), VolumeFileFormat::Unknown);
}

TEST(VolumeFileInfo, refusesOtherFiles) {
    const std::string path = testPath("scene.iv");
    std::ofstream(path) << "#Inventor V2.1 ascii\n";
    try {
        describeVolumeFile(path);
        FAIL() << "no error";
    } catch (const IoError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path + ": not a data file texsplat reads whole; expected texsplat-raw, NumPy "
                         ".npy, NRRD, NetCDF or OpenVDB .vdb");
    }
}

#ifdef TEXSPLAT_WITH_OPENVDB
TEST(VolumeFileInfo, describesEveryGridOfAnOpenVdbFile) {
    openvdb::initialize();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setTransform(openvdb::math::Transform::createLinearTransform(0.5));
    density->getAccessor().setValue({2, 3, 4}, 0.25f);
    density->getAccessor().setValue({5, 3, 4}, -1.5f);
    auto mask = openvdb::BoolGrid::create(false);
    mask->setName("mask");
    mask->getAccessor().setValue({0, 0, 0}, true);
    const std::string path = testPath("two.vdb");
    openvdb::io::File(path).write({density, mask});
    const std::string text = describeVolumeFile(path, 2);
    EXPECT_EQ(text, path + ": OpenVDB, 2 grids\n"
                           "grid 'density' (float)\n"
                           "  values        scalar\n"
                           "  dimensions    4 x 1 x 1 voxels (x, y, z)\n"
                           "  voxel size    0.5 x 0.5 x 0.5\n"
                           "  bounding box  (0.75, 1.25, 1.75) .. (2.75, 1.75, 2.25)\n"
                           "  active voxels 2 of 4\n"
                           "  value range   -1.5 .. 0.25\n"
                           "  histogram (2 bins)\n"
                           "            -1.5 .. -0.625                1 " +
                               std::string(40, '#') +
                               "\n"
                               "          -0.625 .. 0.25                  1 " +
                               std::string(40, '#') +
                               "\n"
                               "  scene         VolumeData { source FILE_VDB fileName \"" +
                               path +
                               "\" gridName \"density\" }\n"
                               "grid 'mask' (bool)\n"
                               "  not readable: texsplat reads float and vec3s grids\n");
}
#endif

} // namespace
} // namespace texsplat::volume
