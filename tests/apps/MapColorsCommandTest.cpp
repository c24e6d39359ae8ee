// Colours as the ecosystem means them (issue 31): a colour map's values are display values, so an
// opaque region classified by a named map shows, in the PNG file's bytes, the map's published
// colour, as matplotlib, ParaView and VTK show it. The file is decoded here by stb_image itself,
// not by texsplat's reader, so that an encoding and its inverse cannot cancel out.

#include "RunCommand.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

namespace texsplat {
namespace {

using test::runTexsplat;

using Bytes = std::array<int, 3>;

// Five slabs along x, 5 voxels each, of the values 0, 26, 128, 230 and 255 over 255: the
// positions t of entries of a 256-entry table, where a listed map's published colour is exact.
constexpr std::array<int, 5> kEntries = {0, 26, 128, 230, 255};
constexpr int kSlab = 5;

struct PublishedMap {
    const char* preset;
    std::array<Bytes, 5> colors; // at kEntries
};

// matplotlib 3.6's tables (Debian 12): `matplotlib.colormaps[name](entry, bytes=True)`.
const std::array<PublishedMap, 6> kMaps = {{
    {"VIRIDIS", {{{68, 1, 84}, {72, 37, 118}, {33, 145, 140}, {189, 223, 38}, {253, 231, 37}}}},
    {"MAGMA", {{{0, 0, 4}, {21, 14, 56}, {183, 55, 121}, {254, 207, 146}, {252, 253, 191}}}},
    {"INFERNO", {{{0, 0, 4}, {24, 12, 60}, {188, 55, 84}, {246, 215, 70}, {252, 255, 164}}}},
    {"PLASMA", {{{13, 8, 135}, {67, 3, 158}, {204, 71, 120}, {252, 206, 37}, {240, 249, 33}}}},
    {"CIVIDIS", {{{0, 34, 78}, {12, 52, 112}, {125, 124, 120}, {229, 207, 82}, {254, 232, 56}}}},
    {"TURBO", {{{48, 18, 59}, {69, 92, 207}, {164, 252, 60}, {195, 37, 3}, {122, 4, 3}}}},
}};

// The published colour within one step of 255 in every channel (the issue asks for 3).
constexpr int kSteps = 1;

struct StbFree {
    void operator()(unsigned char* data) const { stbi_image_free(data); }
};

// The RGBA bytes of a PNG file, as any PNG reader sees them.
struct PngBytes {
    int width = 0;
    int height = 0;
    std::unique_ptr<unsigned char, StbFree> data;

    explicit PngBytes(const std::string& path) {
        int channels = 0;
        data.reset(stbi_load(path.c_str(), &width, &height, &channels, 4));
    }
    Bytes rgb(int x, int y) const {
        const unsigned char* pixel = data.get() + 4 * (std::size_t(y) * width + x);
        return {pixel[0], pixel[1], pixel[2]};
    }
};

class MapColorsCommandTest : public test::ScratchDirectoryTest {
protected:
    void SetUp() override {
        ScratchDirectoryTest::SetUp();
        const int nx = kSlab * static_cast<int>(kEntries.size());
        std::string data;
        for (int z = 0; z < 8; ++z)
            for (int y = 0; y < 8; ++y)
                for (int x = 0; x < nx; ++x) {
                    const float value = static_cast<float>(kEntries[x / kSlab]) / 255.0f;
                    char bytes[sizeof value];
                    std::memcpy(bytes, &value, sizeof value);
                    data.append(bytes, sizeof value);
                }
        write("slabs.raw", "texsplat-raw 1\ndims " + std::to_string(nx) +
                               " 8 8\ntype float32\nendian little\ndata\n" + data);
    }

    // The scene of the slabs seen from +z, orthographic, 8 pixels per voxel, through `colors`
    // (the TransferFunction's colour fields) and an opacity that makes the first voxel opaque.
    std::string scene(const std::string& colors) const {
        return write("slabs.iv",
                     "#Inventor V2.1 ascii\nSeparator {\n"
                     "  OrthographicCamera { position 12 3.5 40 height 10 nearDistance 20 "
                     "farDistance 60 focalDistance 40 }\n"
                     "  TransferFunction { " + colors + " range 0 1 opacities [ 2000, 2000 ] "
                     "unitDistance 0 }\n"
                     "  VolumeData { source FILE_RAW fileName \"slabs.raw\" }\n"
                     "  TextureSplat { }\n}\n");
    }

    // The bytes at the centre of each slab in the PNG `how` renders of `colors`.
    std::array<Bytes, 5> slabColors(const std::string& colors, const std::string& how) const {
        const std::string output = path("slabs.png");
        const auto result = runTexsplat("render " + scene(colors) + " -o " + output +
                                        " --size 250x80 " + how);
        EXPECT_EQ(result.exitCode, 0) << how << ": " << result.standardError;
        const PngBytes png(output);
        EXPECT_TRUE(png.data) << stbi_failure_reason();
        std::array<Bytes, 5> found{};
        for (std::size_t k = 0; png.data && k < found.size(); ++k) {
            // Slab k's centre, x = 2 + 5k in voxels, 8 pixels per voxel about x = 12 at column 125.
            const int x = 125 + (2 + kSlab * static_cast<int>(k) - 12) * 8;
            found[k] = png.rgb(x, 40);
        }
        return found;
    }
};

void expectWithinSteps(const Bytes& found, const Bytes& published, const std::string& what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(found[c], published[c], kSteps)
            << what << " channel " << c << ": found (" << found[0] << ", " << found[1] << ", "
            << found[2] << "), published (" << published[0] << ", " << published[1] << ", "
            << published[2] << ")";
    }
}

TEST_F(MapColorsCommandTest, anOpaqueRegionShowsTheNamedMapsPublishedColor) {
    for (const PublishedMap& map : kMaps) {
        const std::array<Bytes, 5> found =
            slabColors(std::string("preset ") + map.preset, "--backend cpu");
        for (std::size_t k = 0; k < found.size(); ++k) {
            expectWithinSteps(found[k], map.colors[k],
                              std::string(map.preset) + " entry " + std::to_string(kEntries[k]));
        }
    }
}

TEST_F(MapColorsCommandTest, everyBackendAndTheReferenceShowTheSameColors) {
    const PublishedMap& magma = kMaps[1];
    for (const std::string how : {"--backend gl", "--raycast"}) {
        const std::array<Bytes, 5> found = slabColors("preset MAGMA", how);
        for (std::size_t k = 0; k < found.size(); ++k) {
            expectWithinSteps(found[k], magma.colors[k],
                              how + " entry " + std::to_string(kEntries[k]));
        }
    }
}

TEST_F(MapColorsCommandTest, explicitColorsAreWrittenAsGiven) {
    // The example: MAGMA at 0.1 as a newcomer would type it from the published table.
    const std::array<Bytes, 5> found =
        slabColors("colorValues [ 0, 1 ] colors [ 0.0784314 0.0549020 0.2117647, "
                   "0.0784314 0.0549020 0.2117647 ]",
                   "--backend cpu");
    for (const Bytes& color : found) {
        expectWithinSteps(color, {20, 14, 54}, "colors");
    }
}

} // namespace
} // namespace texsplat
