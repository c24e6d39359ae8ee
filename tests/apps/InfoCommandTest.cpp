#include "RunCommand.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <unistd.h>

namespace fs = std::filesystem;
using texsplat::test::runTexsplat;

namespace {

class InfoCommandTest : public texsplat::test::ScratchDirectoryTest {};

TEST_F(InfoCommandTest, printsTheGraphWithItsNonDefaultFields) {
    const std::string path = write("scene.iv", R"(#Inventor V2.1 ascii
Separator {
    DEF pick Switch { whichChild 0 Group { } }
    Switch { whichChild = USE pick . whichChild }
    USE pick
}
)");
    const auto output = runTexsplat("info " + path);
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_EQ(output.standardOutput, "#Inventor V2.1 ascii\n# " + path + R"(: 4 nodes, 0 engines, 1 shared; Group 1, Separator 1, Switch 2

Separator {
    DEF pick Switch {
        whichChild 0
        Group {
        }
    }
    Switch {
        whichChild = USE pick . whichChild
    }
    USE pick
}
)");
}

TEST_F(InfoCommandTest, printsTheReadErrorWithFileLineAndColumn) {
    const std::string path = write("bad.iv", "#Inventor V2.1 ascii\nSwitch { whichChil 1 }\n");
    const auto output = runTexsplat("info " + path);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardOutput, "");
    EXPECT_EQ(output.standardError, "texsplat: error: " + path +
                                        ":2:10: unknown field 'whichChil' of Switch (fields: "
                                        "whichChild)\n");
}

// Usage errors are CLI11's: its message first, its exit code (not 0, not kExitFailure).
TEST_F(InfoCommandTest, needsASceneOrTheReference) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"info", "scene (or --reference) is required\n"},
        {"info --reference scene.iv", "scene excludes --reference\n"},
        {"info --update x.md", "--update requires --reference\n"},
    };
    for (const auto& [arguments, message] : cases) {
        const auto output = runTexsplat(arguments);
        EXPECT_EQ(output.exitCode, 2) << arguments; // a usage error
        const std::string expected = "texsplat: error: " + message;
        EXPECT_EQ(output.standardError.substr(0, expected.size()), expected) << arguments;
    }
}

TEST_F(InfoCommandTest, readsEveryExampleSceneWithTheNodesLibrarysTypes) {
    for (const char* name : {"tornado", "marschner-lobb", "blob", "jet-stream", "aerogel"}) {
        const auto output =
            runTexsplat("info " TEXSPLAT_SOURCE_DIR "/examples/" + std::string(name) + ".iv");
        EXPECT_EQ(output.exitCode, 0) << name << ": " << output.standardError;
        EXPECT_NE(output.standardOutput.find("VolumeData {"), std::string::npos) << name;
    }
}

// The bytes of values 0, 1, ..., count - 1 as little-endian float32.
std::string floatRamp(int count) {
    std::string bytes;
    for (int i = 0; i < count; ++i) {
        const float value = static_cast<float>(i);
        unsigned char word[4];
        std::memcpy(word, &value, 4);
        if (__BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__)
            std::reverse(word, word + 4);
        bytes.append(reinterpret_cast<const char*>(word), 4);
    }
    return bytes;
}

// What a scene needs for a data file: dimensions (x fastest: a (2, 3, 4) array is 4 x 3 x 2),
// voxel size, bounds, active voxels, value range and a histogram whose counts add up.
TEST_F(InfoCommandTest, describesANumpyFile) {
    std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3, 4), }";
    header.resize(128 - 10 - 1, ' ');
    header += '\n';
    const std::string path = write("ramp.npy", std::string("\x93NUMPY\x01\x00", 8) +
                                                   char(header.size()) + '\0' + header +
                                                   floatRamp(24));
    const auto output = runTexsplat("info " + path);
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    const std::string full(40, '#');
    const std::string part(27, '#');
    EXPECT_EQ(output.standardOutput,
              path + ": NumPy .npy, dtype '<f4' (float32), shape (2, 3, 4), C order\n"
                     "  values        scalar\n"
                     "  dimensions    4 x 3 x 2 voxels (x, y, z)\n"
                     "  voxel size    1 x 1 x 1\n"
                     "  bounding box  (-0.5, -0.5, -0.5) .. (3.5, 2.5, 1.5)\n"
                     "  active voxels 24 of 24\n"
                     "  value range   0 .. 23\n"
                     "  histogram (10 bins)\n"
                     "               0 .. 2.3                   3 " + full + "\n"
                     "             2.3 .. 4.6                   2 " + part + "\n"
                     "             4.6 .. 6.9                   2 " + part + "\n"
                     "             6.9 .. 9.2                   3 " + full + "\n"
                     "             9.2 .. 11.5                  2 " + part + "\n"
                     "            11.5 .. 13.8                  2 " + part + "\n"
                     "            13.8 .. 16.1                  3 " + full + "\n"
                     "            16.1 .. 18.4                  2 " + part + "\n"
                     "            18.4 .. 20.7                  2 " + part + "\n"
                     "            20.7 .. 23                    3 " + full + "\n"
                     "  scene         VolumeData { source FILE_NPY fileName \"" + path + "\" }\n");
}

TEST_F(InfoCommandTest, describesATexsplatRawFileOfVectors) {
    const std::string path =
        write("wind.raw", "texsplat-raw 1\ndims 2 1 1\ntype float32\ncomponents 3\n"
                          "spacing 0.5 2 3\norigin 10 20 30\ndata\n" + floatRamp(6));
    const auto output = runTexsplat("info " + path);
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    const std::string text = output.standardOutput;
    EXPECT_EQ(text.substr(0, text.find("  histogram")),
              path + ": texsplat-raw, float32, little endian\n"
                     "  values        vector (3 components)\n"
                     "  dimensions    2 x 1 x 1 voxels (x, y, z)\n"
                     "  voxel size    0.5 x 2 x 3\n"
                     "  bounding box  (9.75, 19, 28.5) .. (10.75, 21, 31.5)\n"
                     "  active voxels 2 of 2\n"
                     "  length range  2.236068 .. 7.071068\n");
    EXPECT_NE(
        text.find("  scene         VolumeData { source FILE_RAW fileName \"" + path + "\" }\n"),
        std::string::npos);
}

// A headerless .raw: the message says which format was expected and how to describe the file,
// and prints none of its bytes.
TEST_F(InfoCommandTest, aHeaderlessRawFileGetsTheFormatNamedNotItsBytes) {
    const std::string path = write("ct.raw", std::string("\x8c\xe9\x02\xfa\x80U\x00\x00", 8));
    const auto output = runTexsplat("info " + path);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardOutput, "");
    EXPECT_EQ(output.standardError,
              "texsplat: error: " + path +
                  ":1:1: expected 'texsplat-raw 1' on the first line, found binary data (a "
                  "headerless raw file? give its layout: texsplat info FILE --dims X,Y,Z --type "
                  "TYPE, or in a scene VolumeData source FILE_RAW_HEADERLESS)\n");
}

// `texsplat info ct.raw --dims 256,256,180 --type uint8`: a headerless raw file described from
// the layout given on the command line, with the VolumeData that reads it.
TEST_F(InfoCommandTest, describesAHeaderlessRawFileFromTheLayoutGiven) {
    std::string bytes(2, '\0'); // two bytes of another program's header
    for (int value = 0; value < 24; ++value)
        bytes += static_cast<char>(value);
    const std::string path = write("ct.raw", bytes);
    const auto output =
        runTexsplat("info " + path + " --dims 4,3,2 --type uint8 --header-bytes 2");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    const std::string text = output.standardOutput;
    EXPECT_EQ(text.substr(0, text.find("  histogram")),
              path + ": headerless raw, uint8, little endian, after 2 header bytes\n"
                     "  values        scalar\n"
                     "  dimensions    4 x 3 x 2 voxels (x, y, z)\n"
                     "  voxel size    1 x 1 x 1\n"
                     "  bounding box  (-0.5, -0.5, -0.5) .. (3.5, 2.5, 1.5)\n"
                     "  active voxels 24 of 24\n"
                     "  value range   0 .. 23\n");
    EXPECT_NE(text.find("  scene         VolumeData { source FILE_RAW_HEADERLESS fileName \"" +
                        path + "\" dimensions 4 3 2 dataType UINT8 headerBytes 2 }\n"),
              std::string::npos)
        << text;

    const auto mismatch = runTexsplat("info " + path + " --dims 4,3,3 --type uint8");
    EXPECT_EQ(mismatch.exitCode, 1);
    EXPECT_EQ(mismatch.standardError,
              "texsplat: error: " + path +
                  ": file size mismatch: the scene describes 4 x 3 x 3 voxels x 1 component x 1 "
                  "bytes (uint8) = 36 bytes, plus 0 header bytes = 36 bytes, but the file has 26 "
                  "bytes\n");
    const auto bad = [&](const std::string& options, const std::string& message) {
        const auto result = runTexsplat("info " + path + " " + options);
        EXPECT_EQ(result.exitCode, 1) << options;
        EXPECT_EQ(result.standardError, "texsplat: error: " + message + "\n") << options;
    };
    bad("--type uint8", "--type: only with --dims, for a headerless raw file (other files say "
                        "their own layout)");
    bad("--dims 4,3", "--dims: expected X,Y,Z (voxels along x, y and z, x fastest in the file), "
                      "got '4,3'");
    bad("--dims 4,0,2", "--dims: expected X,Y,Z of whole numbers from 1 to 1e9, got '4,0,2'");
    bad("--dims 4,3,2 --type int64", "--type: expected uint8, int8, uint16, int16, uint32, int32, "
                                     "float32 or float64, got 'int64'");
    bad("--dims 4,3,2 --components 2", "--components: expected 1 or 3, got '2'");
}

// The values are streamed from the file, never held as a grid: a 128³ file of bytes (8 MiB as a
// float grid, what `info` allocated before) is described under a limit of 4 MiB.
TEST_F(InfoCommandTest, streamsTheValuesWithinTheMemoryLimit) {
    const std::string path =
        write("big.raw", "texsplat-raw 1\ndims 128 128 128\ntype uint8\ndata\n" +
                             std::string(128 * 128 * 128, '\x07'));
    const auto output = runTexsplat("info " + path + " --memory-limit 4M");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("  active voxels 2097152 of 2097152\n"
                                         "  value range   7 .. 7\n"),
              std::string::npos)
        << output.standardOutput;
    const auto bad = runTexsplat("info " + path + " --memory-limit lots");
    EXPECT_EQ(bad.standardError, "texsplat: error: --memory-limit: expected a byte count such as "
                                 "512M or 8G, got 'lots'\n");
}

// `--scene` prints a scene that draws the data file, which reads back as a scene.
TEST_F(InfoCommandTest, printsASceneThatDrawsADataFile) {
    const std::string path =
        write("ramp.raw", "texsplat-raw 1\ndims 4 3 2\ntype float32\ndata\n" + floatRamp(24));
    const auto output = runTexsplat("info " + path + " --scene");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_EQ(output.standardOutput.rfind("#Inventor V2.1 ascii\n", 0), 0u);
    EXPECT_NE(output.standardOutput.find("    VolumeData { source FILE_RAW fileName \"" + path +
                                         "\" }\n"),
              std::string::npos)
        << output.standardOutput;
    const std::string scene = write("ramp.iv", output.standardOutput);
    const auto read = runTexsplat("info " + scene);
    EXPECT_EQ(read.exitCode, 0) << read.standardError;
    EXPECT_NE(read.standardOutput.find("TextureSplat"), std::string::npos);
    const auto notData = runTexsplat("info " + scene + " --scene");
    EXPECT_EQ(notData.standardError,
              "texsplat: error: --scene: " + scene +
                  " is not a data file texsplat reads (texsplat-raw, .npy, NRRD, NetCDF, .vdb, or "
                  "headerless raw with --dims)\n");
}

TEST_F(InfoCommandTest, aBrokenDataFileGetsTheReadersMessage) {
    const std::string path = write("broken.npy", std::string("\x93NUMPY\x07\x00", 8));
    const auto output = runTexsplat("info " + path);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: " + path +
                                        ": unsupported .npy format version 7.0; this reader "
                                        "reads versions 1, 2 and 3\n");
}

TEST_F(InfoCommandTest, referenceListsTypesWithFieldsDefaultsAndMeanings) {
    const auto output = runTexsplat("info --reference");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find(R"(### Switch

Node, derived from Group. Takes child nodes. Standard Inventor type.

| field | type | default | meaning |
|---|---|---|---|
| whichChild | SFInt32 | `-1` | Index of the one child to traverse (from 0); -1 traverses none, -3 all |
)"),
              std::string::npos)
        << output.standardOutput;
}

TEST_F(InfoCommandTest, docsHoldTheCurrentGeneratedReference) {
    const std::string docs = read(TEXSPLAT_SOURCE_DIR "/docs/scene-files.md");
    const std::string copy = write("scene-files.md", docs);
    const auto output = runTexsplat("info --reference --update " + copy);
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_TRUE(read(copy) == docs)
        << "docs/scene-files.md is out of date: run `texsplat info --reference --update "
           "docs/scene-files.md`";
}

TEST_F(InfoCommandTest, updateNeedsTheGeneratedSectionMarkers) {
    const std::string path = write("plain.md", "# no markers\n");
    const auto output = runTexsplat("info --reference --update " + path);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError,
              "texsplat: error: " + path +
                  ": expected the lines '<!-- BEGIN GENERATED REFERENCE (texsplat info "
                  "--reference): do not edit by hand -->' and then '<!-- END GENERATED "
                  "REFERENCE -->' around the generated reference\n");
    EXPECT_EQ(read(path), "# no markers\n");
}

} // namespace
