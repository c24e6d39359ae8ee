// Bricks read from files: each rank reads only its brick of every file format (raw and NPY by
// rows, NRRD raw by rows and gzip streamed, NetCDF by hyperslabs, OpenVDB by clipping to the
// brick's box), and the picture is the one-process picture.

#include "DistributedTesting.h"

#include <gtest/gtest.h>

#include <zlib.h>

#include <unistd.h>

#ifdef TEXSPLAT_WITH_OPENVDB
#include <openvdb/openvdb.h>
#endif

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace texsplat::test {
namespace {

namespace fs = std::filesystem;

// The test volume: a lopsided blob over 20 x 18 x 16 voxels, x fastest.
constexpr int kX = 20;
constexpr int kY = 18;
constexpr int kZ = 16;

float valueAt(int x, int y, int z) {
    const float u = (static_cast<float>(x) - 8.0f) / 7.0f;
    const float v = (static_cast<float>(y) - 9.5f) / 6.0f;
    const float w = (static_cast<float>(z) - 7.0f) / 5.0f;
    return std::exp(-(u * u + v * v + w * w)) +
           0.1f * std::sin(0.7f * static_cast<float>(x + 2 * y));
}

// The values in file order: x fastest, or z fastest (a Fortran-order array of shape (z, y, x)).
std::vector<float> values(bool zFastest = false) {
    std::vector<float> out;
    out.reserve(std::size_t{kX} * kY * kZ);
    const int outer = zFastest ? kX : kZ;
    const int inner = zFastest ? kZ : kX;
    for (int i = 0; i < outer; ++i) {
        for (int y = 0; y < kY; ++y) {
            for (int j = 0; j < inner; ++j) {
                out.push_back(zFastest ? valueAt(i, y, j) : valueAt(j, y, i));
            }
        }
    }
    return out;
}

void writeBytes(const fs::path& path, const std::string& head, const std::vector<float>& data) {
    std::ofstream out(path, std::ios::binary);
    out << head;
    out.write(reinterpret_cast<const char*>(data.data()),
              static_cast<std::streamsize>(data.size() * sizeof(float)));
}

// A .npy of shape (z, y, x), or (z, y, x, 3) with `vectors`: each voxel's vector turns with x
// and grows with the blob.
void writeNpy(const fs::path& path, bool fortran, bool vectors = false) {
    std::string header = std::string("{'descr': '<f4', 'fortran_order': ") +
                         (fortran ? "True" : "False") + ", 'shape': (" + std::to_string(kZ) + ", " +
                         std::to_string(kY) + ", " + std::to_string(kX) + (vectors ? ", 3" : "") +
                         "), }";
    while ((10 + header.size() + 1) % 64 != 0) {
        header += ' ';
    }
    header += '\n';
    const auto length = static_cast<std::uint16_t>(header.size());
    std::string head = "\x93NUMPY\x01";
    head += '\0';
    head += static_cast<char>(length & 0xff);
    head += static_cast<char>(length >> 8);
    if (!vectors) {
        writeBytes(path, head + header, values(fortran));
        return;
    }
    std::vector<float> data;
    for (int z = 0; z < kZ; ++z) {
        for (int y = 0; y < kY; ++y) {
            for (int x = 0; x < kX; ++x) {
                const float size = valueAt(x, y, z);
                const float angle = 0.3f * static_cast<float>(x + y);
                data.insert(data.end(), {size * std::cos(angle), size * std::sin(angle),
                                         0.2f * size});
            }
        }
    }
    writeBytes(path, head + header, data);
}

std::string nrrdHeader(const std::string& encoding) {
    return "NRRD0004\ntype: float\ndimension: 3\nsizes: " + std::to_string(kX) + " " +
           std::to_string(kY) + " " + std::to_string(kZ) +
           "\nendian: little\nencoding: " + encoding + "\n\n";
}

void writeGzipNrrd(const fs::path& path) {
    writeBytes(path, nrrdHeader("gzip"), {});
    const std::vector<float> data = values();
    gzFile out = gzopen(path.c_str(), "ab");
    ASSERT_NE(out, nullptr);
    gzwrite(out, data.data(), static_cast<unsigned>(data.size() * sizeof(float)));
    gzclose(out);
}

// A NetCDF file through ncgen (netcdf-bin); false when ncgen is not installed.
bool writeNetCdf(const fs::path& path) {
    if (std::system("command -v ncgen >/dev/null 2>&1") != 0) {
        return false;
    }
    std::ostringstream cdl;
    cdl << "netcdf blob {\ndimensions:\n z = " << kZ << " ;\n y = " << kY << " ;\n x = " << kX
        << " ;\nvariables:\n float density(z, y, x) ;\ndata:\n density = ";
    const std::vector<float> data = values();
    for (std::size_t i = 0; i < data.size(); ++i) {
        cdl << (i > 0 ? ", " : "") << data[i];
    }
    cdl << " ;\n}\n";
    const fs::path text = path.string() + ".cdl";
    std::ofstream(text) << cdl.str();
    const std::string command = "ncgen -o '" + path.string() + "' '" + text.string() + "'";
    return std::system(command.c_str()) == 0;
}

#ifdef TEXSPLAT_WITH_OPENVDB
// A sparse OpenVDB grid: the blob's voxels above 0.3, so that some leaves are empty.
void writeVdb(const fs::path& path) {
    openvdb::initialize();
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    openvdb::FloatGrid::Accessor access = grid->getAccessor();
    for (int z = 0; z < kZ; ++z) {
        for (int y = 0; y < kY; ++y) {
            for (int x = 0; x < kX; ++x) {
                if (valueAt(x, y, z) > 0.3f) {
                    access.setValue(openvdb::Coord(x + 3, y - 2, z), valueAt(x, y, z));
                }
            }
        }
    }
    openvdb::io::File(path.string()).write({grid});
}
#endif

// A folder every rank sees, written by rank 0 alone.
class BrickReadTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        std::string name;
        if (rank() == 0) {
            name = (fs::temp_directory_path() / ("texsplat-bricks-" + std::to_string(::getpid())))
                       .string();
            fs::create_directories(name);
            writeBytes(fs::path(name) / "headerless.raw", "", values());
            writeNpy(fs::path(name) / "c.npy", false);
            writeNpy(fs::path(name) / "fortran.npy", true);
            writeNpy(fs::path(name) / "vectors.npy", false, true);
            writeBytes(fs::path(name) / "raw.nrrd", nrrdHeader("raw"), values());
            writeGzipNrrd(fs::path(name) / "gzip.nrrd");
            hasNetCdf() = writeNetCdf(fs::path(name) / "blob.nc");
#ifdef TEXSPLAT_WITH_OPENVDB
            writeVdb(fs::path(name) / "blob.vdb");
#endif
        }
        int length = static_cast<int>(name.size());
        MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
        name.resize(static_cast<std::size_t>(length));
        MPI_Bcast(name.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
        int netCdf = hasNetCdf() ? 1 : 0;
        MPI_Bcast(&netCdf, 1, MPI_INT, 0, MPI_COMM_WORLD);
        hasNetCdf() = netCdf != 0;
        folder() = name;
    }

    static void TearDownTestSuite() {
        MPI_Barrier(MPI_COMM_WORLD);
        if (rank() == 0) {
            fs::remove_all(folder());
        }
    }

    static std::string& folder() {
        static std::string path;
        return path;
    }
    static bool& hasNetCdf() {
        static bool has = false;
        return has;
    }

    // The PSNR of `volume` (a VolumeData's fields) drawn by `splat` split over the ranks against
    // one process.
    static double psnrOf(const std::string& volume, const std::string& splat = "TextureSplat { }") {
        const std::string scene = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset HOT opacityValues [ 0, 0.3, 1.2 ] opacities [ 0, 0, 6 ] }
    VolumeData { )" + volume + R"( }
    )" + splat + R"(
})";
        View view;
        view.direction = {-1.0f, -0.7f, -0.4f};
        return psnrAgainstOneProcess(scene, view);
    }

    static std::string file(const std::string& source, const std::string& name) {
        return "source " + source + " fileName \"" + folder() + "/" + name + "\"";
    }
};

TEST_F(BrickReadTest, readsEachFormatsBricksAsOneProcessReadsTheWhole) {
    std::vector<std::string> volumes = {
        file("FILE_RAW_HEADERLESS", "headerless.raw") + " dimensions " + std::to_string(kX) + " " +
            std::to_string(kY) + " " + std::to_string(kZ),
        file("FILE_NPY", "c.npy"),
        file("FILE_NPY", "fortran.npy"),
        file("FILE_NRRD", "raw.nrrd"),
        file("FILE_NRRD", "gzip.nrrd"),
    };
    if (hasNetCdf()) {
        volumes.push_back(file("FILE_NETCDF", "blob.nc") + " gridName \"density\"");
    }
#ifdef TEXSPLAT_WITH_OPENVDB
    volumes.push_back(file("FILE_VDB", "blob.vdb") + " gridName \"density\"");
#endif
    for (const std::string& volume : volumes) {
        const double psnr = psnrOf(volume);
        if (rank() == 0) {
            EXPECT_GE(psnr, kMinimumPsnr) << volume << ", " << ranks() << " ranks";
        }
    }
}

TEST_F(BrickReadTest, readsVectorBricksAsOneProcessReadsTheWhole) {
    // A (z, y, x, 3) .npy's bricks become vector grids (the file's floats read straight into
    // them); combined splats draw their magnitudes and the whole grid's marks.
    const double psnr = psnrOf(file("FILE_NPY", "vectors.npy"),
                               "CombinedSplat { markType SCRATCHES markDensity 2 }");
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

} // namespace
} // namespace texsplat::test
