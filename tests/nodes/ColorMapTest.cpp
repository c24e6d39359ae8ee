// The listed colour-map presets against matplotlib's published tables, and the reader of
// ParaView's colour-map JSON files.

#include "nodes/TransferFunction.h"
#include "nodes/colormap/ParaViewColorMap.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "scenegraph/Error.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace texsplat::nodes {
namespace {

using test::errorOf;

struct PublishedSample {
    ColorPreset preset;
    int entry; // of matplotlib's 256
    glm::vec3 color;
};

// Entries 0, 128 and 255 of matplotlib's _cm_listed.py (magma, inferno, plasma, cividis) and of
// Google's turbo table as matplotlib ships it.
const PublishedSample kSamples[] = {
    {ColorPreset::Magma, 0, {0.001462f, 0.000466f, 0.013866f}},
    {ColorPreset::Magma, 128, {0.716387f, 0.214982f, 0.475290f}},
    {ColorPreset::Magma, 255, {0.987053f, 0.991438f, 0.749504f}},
    {ColorPreset::Inferno, 128, {0.735683f, 0.215906f, 0.330245f}},
    {ColorPreset::Inferno, 255, {0.988362f, 0.998364f, 0.644924f}},
    {ColorPreset::Plasma, 0, {0.050383f, 0.029803f, 0.527975f}},
    {ColorPreset::Plasma, 128, {0.798216f, 0.280197f, 0.469538f}},
    {ColorPreset::Plasma, 255, {0.940015f, 0.975158f, 0.131326f}},
    {ColorPreset::Cividis, 0, {0.000000f, 0.135112f, 0.304751f}},
    {ColorPreset::Cividis, 128, {0.488697f, 0.485318f, 0.471008f}},
    {ColorPreset::Cividis, 255, {0.995737f, 0.909344f, 0.217772f}},
    {ColorPreset::Turbo, 0, {0.18995f, 0.07176f, 0.23217f}},
    {ColorPreset::Turbo, 128, {0.64362f, 0.98999f, 0.23356f}},
    {ColorPreset::Turbo, 255, {0.47960f, 0.01583f, 0.01055f}},
};

TEST(ColorMap, listedPresetsMatchThePublishedTables) {
    const auto tf = TransferFunction::create();
    for (const PublishedSample& sample : kSamples) {
        tf->preset.setValue(sample.preset);
        const glm::vec3 color = tf->colorAt(float(sample.entry) / 255.0f);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(color[c], sample.color[c], 1e-6f)
                << kColorPresetNames.name(int(sample.preset)) << " entry " << sample.entry;
        }
    }
}

const std::string kCoolToWarm = TEXSPLAT_TEST_DATA_DIR "/paraview-cool-to-warm.json";

TEST(ColorMap, aSceneFileNamesItsColorMapRelativeToItsFolder) {
    registerNodeTypes();
    const std::filesystem::path folder = test::testPath("scene");
    std::filesystem::create_directories(folder);
    std::filesystem::copy_file(kCoolToWarm, folder / "map.json",
                               std::filesystem::copy_options::overwrite_existing);
    std::ofstream(folder / "scene.iv")
        << "#Inventor V2.1 ascii\nDEF tf TransferFunction { colorMapFile \"map.json\" }\n";
    const auto tf = std::dynamic_pointer_cast<TransferFunction>(
        sg::SceneReader::readFile((folder / "scene.iv").string()));
    ASSERT_TRUE(tf);
    EXPECT_FLOAT_EQ(tf->colorAt(1.0f).r, 0.705882352941f);
}

TEST(ColorMap, readsAParaViewColorMapFile) {
    const colormap::ParaViewColorMap map = colormap::readParaViewColorMap(kCoolToWarm);
    EXPECT_EQ(map.name, "Cool to Warm");
    EXPECT_EQ(map.colorSpace, "Diverging");
    // The x of -0.15, 0, 0.15 rescaled to the transfer function's t.
    EXPECT_EQ(map.positions, (std::vector<float>{0.0f, 0.5f, 1.0f}));
    ASSERT_EQ(map.colors.size(), 3U);
    EXPECT_FLOAT_EQ(map.colors[1].g, 0.865f);
}

TEST(ColorMap, colorMapFileReplacesThePresetRelativeToTheSceneFile) {
    const auto tf = TransferFunction::create();
    tf->preset.setValue(ColorPreset::Magma);
    tf->colorMapFile = std::string("paraview-cool-to-warm.json");
    tf->setBaseDirectory(TEXSPLAT_TEST_DATA_DIR);
    const glm::vec3 low = tf->colorAt(0.0f);
    EXPECT_FLOAT_EQ(low.b, 0.752941176471f);
    const glm::vec3 middle = tf->colorAt(0.25f);
    EXPECT_FLOAT_EQ(middle.r, 0.5f * (0.23137254902f + 0.865f));
    // Explicit colours still win.
    tf->colorValues.setValue({0.0f});
    tf->colors.setValue({glm::vec3(1.0f, 0.0f, 0.0f)});
    EXPECT_EQ(tf->colorAt(0.25f), glm::vec3(1.0f, 0.0f, 0.0f));
}

TEST(ColorMap, aMissingFileNamesThePathTried) {
    const auto tf = TransferFunction::create();
    tf->colorMapFile = std::string("no-such-map.json");
    tf->setBaseDirectory("/nonexistent/scenes");
    EXPECT_EQ(errorOf<IoError>([&] { tf->validate(); }),
              "/nonexistent/scenes/no-such-map.json: cannot open: No such file or directory");
}

std::string parseError(const std::string& text) {
    return errorOf<Error>([&] { colormap::parseParaViewColorMap(text, "map.json"); });
}

TEST(ColorMap, badJsonIsLocated) {
    EXPECT_EQ(parseError("[\n  {\n    \"RGBPoints\" : [0, 1, 1, 1,]\n  }\n]"),
              "map.json:3:31: not valid JSON: syntax error while parsing value - unexpected ']'; "
              "expected '[', '{', or a literal");
    EXPECT_EQ(parseError(""), "map.json:1:1: not valid JSON: syntax error while parsing value - "
                              "unexpected end of input; expected '[', '{', or a literal");
}

TEST(ColorMap, aNumberBeyondDoubleIsNamed) {
    // nlohmann throws out_of_range, not parse_error, here: it escaped the reader (found by
    // fuzz_colormap_reader).
    EXPECT_EQ(parseError("[{\"RGBPoints\": [0, 1e999, 0, 0]}]"),
              "map.json: not valid JSON: number overflow parsing '1e999'");
}

TEST(ColorMap, jsonNestedAMillionDeepIsRefusedBeforeItIsParsed) {
    // Copying the parsed document recursed once a level: a stack overflow (100 000 levels
    // with a 4 MB stack). The depth is counted before nlohmann sees the text.
    const std::string deep = "[{\"RGBPoints\": " + std::string(1000000, '[') + "]}]";
    EXPECT_EQ(parseError(deep), "map.json:1:270: JSON objects and arrays nested deeper than the "
                                "limit of 256 levels");
    // As deep as the limit, the text is parsed (and found to be no colour map).
    const std::string limit = std::string(256, '[') + std::string(256, ']');
    EXPECT_EQ(parseError(limit), "map.json: expected a ParaView colour map, a list of objects with "
                                 "\"RGBPoints\", got array");
}

TEST(ColorMap, jsonThatIsNoColorMapIsNamed) {
    EXPECT_EQ(parseError("42"), "map.json: expected a ParaView colour map, a list of objects with "
                                "\"RGBPoints\", got number");
    EXPECT_EQ(parseError("[{\"Name\": \"m\"}]"),
              "map.json: colour map 'm': has no \"RGBPoints\" list [x, r, g, b, …]");
    EXPECT_EQ(parseError("[{\"RGBPoints\": [0, 1, 1]}]"),
              "map.json: RGBPoints must hold x, r, g, b for each point (a multiple of 4 numbers, "
              "at least 4), got 3 numbers");
    EXPECT_EQ(parseError("[{\"RGBPoints\": [1, 0, 0, 0, 0, 1, 1, 1]}]"),
              "map.json: the x of RGBPoints must not decrease, but RGBPoints[4] = 0 follows 1");
    EXPECT_EQ(parseError("[{\"RGBPoints\": [0, 0, 2, 0]}]"),
              "map.json: RGBPoints[2] is a colour component and must lie in [0, 1], got 2");
    EXPECT_EQ(parseError("[{\"RGBPoints\": [0, \"red\", 0, 0]}]"),
              "map.json: RGBPoints[1] must be a number, got \"red\"");
}

} // namespace
} // namespace texsplat::nodes
