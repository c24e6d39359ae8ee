#include "RunCommand.h"

#include "nodes/image/ImageIo.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using texsplat::test::runTexsplat;

namespace {

// A small strict JSON reader, enough to check that `texsplat kernel --json` prints one valid
// object and to look numbers up by path.
struct Json {
    enum class Type { Null, Boolean, Number, String, Array, Object } type = Type::Null;
    double number = 0.0;
    std::string text;
    std::vector<Json> items;
    std::map<std::string, Json> members;

    const Json& operator[](const std::string& key) const {
        const auto it = members.find(key);
        if (type != Type::Object || it == members.end())
            throw std::runtime_error("no member " + key);
        return it->second;
    }
    const Json& operator[](size_t index) const { return items.at(index); }
};

class JsonReader {
public:
    explicit JsonReader(const std::string& text) : mText(text) {}

    Json document() {
        Json value = parseValue();
        skipSpace();
        if (mAt != mText.size())
            fail("trailing characters");
        return value;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("JSON at " + std::to_string(mAt) + ": " + what);
    }
    void skipSpace() {
        while (mAt < mText.size() && std::isspace(static_cast<unsigned char>(mText[mAt])))
            ++mAt;
    }
    bool take(char c) {
        skipSpace();
        if (mAt < mText.size() && mText[mAt] == c) {
            ++mAt;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!take(c))
            fail(std::string("expected ") + c);
    }
    bool takeWord(const std::string& word) {
        skipSpace();
        if (mText.compare(mAt, word.size(), word) != 0)
            return false;
        mAt += word.size();
        return true;
    }
    std::string parseString() {
        expect('"');
        std::string result;
        while (mAt < mText.size() && mText[mAt] != '"') {
            if (mText[mAt] == '\\')
                ++mAt;
            result += mText[mAt++];
        }
        expect('"');
        return result;
    }
    Json parseValue() {
        Json value;
        skipSpace();
        if (take('{')) {
            value.type = Json::Type::Object;
            if (take('}'))
                return value;
            do {
                skipSpace();
                const std::string key = parseString();
                expect(':');
                value.members[key] = parseValue();
            } while (take(','));
            expect('}');
        } else if (take('[')) {
            value.type = Json::Type::Array;
            if (take(']'))
                return value;
            do
                value.items.push_back(parseValue());
            while (take(','));
            expect(']');
        } else if (mAt < mText.size() && mText[mAt] == '"') {
            value.type = Json::Type::String;
            value.text = parseString();
        } else if (takeWord("null")) {
            value.type = Json::Type::Null;
        } else if (takeWord("true") || takeWord("false")) {
            value.type = Json::Type::Boolean;
        } else {
            size_t used = 0;
            try {
                value.number = std::stod(mText.substr(mAt), &used);
            } catch (const std::exception&) {
                fail("expected a value");
            }
            value.type = Json::Type::Number;
            mAt += used;
        }
        return value;
    }

    const std::string& mText;
    size_t mAt = 0;
};

Json kernelJson(const std::string& arguments) {
    const auto output = runTexsplat("kernel --json " + arguments);
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    return JsonReader(output.standardOutput).document();
}

constexpr double kHalfUnit5 = 0.5e-5;

} // namespace

TEST(KernelCommand, jsonHoldsThePapersNumbersForThePrintedKernel) {
    const Json json = kernelJson("");
    EXPECT_EQ(json["kernel"].text, "paper");
    EXPECT_EQ(json["t"].number, 1.556228);
    EXPECT_EQ(json["s"].number, 0.889392);
    EXPECT_EQ(json["coefficients"]["p"][0].number, 0.557526);
    EXPECT_EQ(json["coefficients"]["p"][1].number, -1.157743);
    EXPECT_EQ(json["coefficients"]["p"][2].number, 0.671033);
    EXPECT_EQ(json["coefficients"]["q"][0].number, 0.067599);
    EXPECT_EQ(json["coefficients"]["q"][1].number, 0.282474);
    const Json& lattice = json["lattice3d"];
    EXPECT_NEAR(lattice["relative_rms"].number, 0.00119, kHalfUnit5);
    EXPECT_NEAR(lattice["min_deviation"].number, -0.00233, kHalfUnit5);
    EXPECT_NEAR(lattice["max_deviation"].number, 0.00534, kHalfUnit5);
    for (size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(lattice["min_at"][i].number, 0.26, 0.005);
    EXPECT_NEAR(lattice["max_at"][0].number, 0.5, 1e-6);
    EXPECT_NEAR(lattice["max_at"][1].number, 0.5, 1e-6);
    EXPECT_NEAR(lattice["max_at"][2].number, 0.0, 1e-6);
    const Json& layer = json["layer2d"];
    EXPECT_NEAR(layer["max"].number, 1.00249, kHalfUnit5);
    EXPECT_NEAR(layer["min"].number, 0.99845, kHalfUnit5);
    EXPECT_NEAR(layer["max_at"][0].number, 0.5, 1e-6);
    EXPECT_NEAR(layer["min_at"][0].number, 0.25, 0.005);
}

TEST(KernelCommand, jsonOfTheOptimizedKernelIsThePapersMinimum) {
    const Json json = kernelJson("--kernel optimized");
    EXPECT_EQ(json["kernel"].text, "optimized");
    EXPECT_NEAR(json["t"].number, 1.556228, 5e-6);
    EXPECT_NEAR(json["s"].number, 0.889392, 5e-6);
    EXPECT_NEAR(json["coefficients"]["p"][0].number, 0.557526, 2e-6);
    EXPECT_NEAR(json["lattice3d"]["relative_rms"].number, 0.00119, kHalfUnit5);
    EXPECT_GT(json["optimizer"]["path"].items.size(), 1u);
}

TEST(KernelCommand, jsonOfTheGaussianHasNoCubicCoefficients) {
    const Json json = kernelJson("--kernel gaussian");
    EXPECT_EQ(json["coefficients"].type, Json::Type::Null);
    EXPECT_EQ(json["t"].number, 1.556228);
    EXPECT_GT(json["lattice3d"]["relative_rms"].number, 0.01);
}

TEST(KernelCommand, tablePrintsThePaperSideBySide) {
    const auto output = runTexsplat("kernel");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("support t                    1.556228     1.556228"),
              std::string::npos)
        << output.standardOutput;
    EXPECT_NE(output.standardOutput.find("Gaussian of the same extent"), std::string::npos);
}

TEST(KernelCommand, optimizeReportsProgressAndResult) {
    const auto output = runTexsplat("kernel --optimize");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("result: t = 1.55622"), std::string::npos)
        << output.standardOutput;
    EXPECT_NE(output.standardError.find("texsplat kernel: restart 0 iteration 0"),
              std::string::npos);
}

TEST(KernelCommand, spacingReportsBothAnisotropicAnswers) {
    const auto output = runTexsplat("kernel --spacing 1,1,1.2");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("(a) paper kernel scaled by the spacing"),
              std::string::npos);
    EXPECT_NE(output.standardOutput.find("(b) rotationally symmetric kernel"), std::string::npos);
}

TEST(KernelCommand, writesTextureAndPlot) {
    const std::string texture = ::testing::TempDir() + "kernel_command_texture.pfm";
    const std::string plot = ::testing::TempDir() + "kernel_command_plot.svg";
    const auto output =
        runTexsplat("kernel --json --texture " + texture + " --resolution 32 --plot " + plot);
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    std::ifstream pfm(texture, std::ios::binary | std::ios::ate);
    const size_t header = std::string("Pf\n32 32\n-1.0\n").size();
    EXPECT_EQ(static_cast<size_t>(pfm.tellg()), header + 32 * 32 * 4);
    std::ifstream svg(plot);
    std::string first;
    std::getline(svg, first);
    EXPECT_EQ(first.rfind("<svg", 0), 0u);
    EXPECT_NE(output.standardError.find("texture adds up to"), std::string::npos);
    std::remove(texture.c_str());
    std::remove(plot.c_str());
}

TEST(KernelCommand, jsonNumbersAreInTheirShortestRoundTripForm) {
    const auto output = runTexsplat("kernel --json");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    // %.17g printed 1.5562279999999999.
    EXPECT_NE(output.standardOutput.find("\"t\": 1.556228,"), std::string::npos)
        << output.standardOutput;
    EXPECT_NE(output.standardOutput.find("\"spacing\": [1, 1, 1],"), std::string::npos);
}

TEST(KernelCommand, tableFitsTheGaussianToTheGivenSupport) {
    const auto output = runTexsplat("kernel --support 2");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("Gaussian of the same extent (truncated gaussian, "
                                         "sigma = 0.6064868, t = 2, best sigma"),
              std::string::npos)
        << output.standardOutput;
}

class KernelCommandTest : public texsplat::test::ScratchDirectoryTest {};

TEST_F(KernelCommandTest, textureFormatFollowsTheExtension) {
    std::vector<std::string> names = {"t.png", "t.PNG"};
    if (texsplat::image::isExrSupported())
        names.push_back("t.exr");
    for (const std::string& name : names) {
        const auto output =
            runTexsplat("kernel --json --texture " + path(name) + " --resolution 16");
        EXPECT_EQ(output.exitCode, 0) << output.standardError;
        const texsplat::image::Image image = texsplat::image::readImage(path(name));
        EXPECT_EQ(image.sizeString(), "16x16");
        // The centre texels hold f near its peak f(0) = 0.70, in every channel.
        const glm::vec4 centre = image.pixel(8, 8);
        EXPECT_NEAR(centre.a, 0.68, 0.02) << name;
        EXPECT_NEAR(centre.r, centre.a, 1e-6) << name;
        EXPECT_NE(output.standardError.find("texture " + path(name) + ": 16x16 texels"),
                  std::string::npos)
            << output.standardError;
    }
}

TEST_F(KernelCommandTest, otherTextureAndPlotExtensionsFailBeforeAnyWork) {
    struct BadCase {
        std::string arguments;
        std::string message;
        std::string file;
    };
    std::vector<BadCase> cases = {
        {"kernel --json --texture " + path("t.tif"),
         path("t.tif") + ": unknown texture extension '.tif' (supported: .pfm, .exr, .png)",
         path("t.tif")},
        {"kernel --json --texture " + path("texture"),
         path("texture") + ": no texture extension (supported: .pfm, .exr, .png)",
         path("texture")},
        {"kernel --plot " + path("p.png"),
         path("p.png") + ": unknown plot extension '.png' (supported: .svg)", path("p.png")},
    };
    if (!texsplat::image::isExrSupported())
        cases.push_back({"kernel --json --texture " + path("t.exr"),
                         path("t.exr") + ": OpenEXR support is not built in (configure with "
                                         "-DTEXSPLAT_WITH_EXR=ON)",
                         path("t.exr")});
    for (const BadCase& badCase : cases) {
        const auto output = runTexsplat(badCase.arguments);
        EXPECT_EQ(output.exitCode, 1) << badCase.arguments;
        EXPECT_EQ(output.standardOutput, "") << badCase.arguments;
        EXPECT_EQ(output.standardError, "texsplat: error: " + badCase.message + "\n");
        EXPECT_FALSE(std::filesystem::exists(badCase.file)) << badCase.file;
    }
}

TEST_F(KernelCommandTest, badOptionsFailWithClearMessages) {
    // A texture path in the scratch directory: none of these may write it.
    const std::string texture = path("t.pfm");
    const struct {
        std::string arguments;
        const char* message;
    } cases[] = {
        {"kernel --optimize --start 0.9,0.8,-2,0.1",
         "texsplat: error: optimizer start: support t = 0.8 must be > knot s = 0.9\n"},
        {"kernel --optimize --start -1,1.5,-2,0.1",
         "texsplat: error: optimizer start: knot s = -1 must be > 0\n"},
        {"kernel --optimize --start nan,1.5,-2,0.1",
         "texsplat: error: optimizer start: knot s = nan is not finite\n"},
        {"kernel --optimize --start 1,2",
         "texsplat: error: --start: expected 4 comma-separated numbers, got '1,2'\n"},
        {"kernel --spacing 1,x,1", "texsplat: error: --spacing: 'x' is not a number\n"},
        {"kernel --spacing 1,0,1",
         "texsplat: error: --spacing: lattice spacing (1, 0, 1) must be finite and > 0\n"},
        {"kernel --json --spacing 1e-10,1,1",
         "texsplat: error: --spacing: lattice spacing (1e-10, 1, 1) must have its largest "
         "spacing at most 4 times its smallest (the run time grows with the ratio)\n"},
        {"kernel --json --kernel optimized --support 1e6",
         "texsplat: error: --support: kernel support 1e+06 must be in (0.866025, 4] on lattice "
         "spacing (1, 1, 1): more than half the cell diagonal (or some points are out of every "
         "kernel's reach) and at most 4 times the cube root of the cell volume (the run time "
         "grows as t³ over the volume)\n"},
        {"kernel --json --kernel gaussian --support 1e-6",
         "texsplat: error: --support: kernel support 1e-06 must be in (0.866025, 4] on lattice "
         "spacing (1, 1, 1): more than half the cell diagonal (or some points are out of every "
         "kernel's reach) and at most 4 times the cube root of the cell volume (the run time "
         "grows as t³ over the volume)\n"},
        {"kernel --json --kernel optimized --spacing 1,1,4 --support 2",
         "texsplat: error: --support: kernel support 2 must be in (2.12132, 6.3496] on lattice "
         "spacing (1, 1, 4): more than half the cell diagonal (or some points are out of every "
         "kernel's reach) and at most 4 times the cube root of the cell volume (the run time "
         "grows as t³ over the volume)\n"},
        // The table optimizes on the cubic lattice too, where 6 is too large.
        {"kernel --spacing 2,2,2 --support 6",
         "texsplat: error: --support: kernel support 6 must be in (0.866025, 4] on lattice "
         "spacing (1, 1, 1): more than half the cell diagonal (or some points are out of every "
         "kernel's reach) and at most 4 times the cube root of the cell volume (the run time "
         "grows as t³ over the volume)\n"},
        {"kernel --json --texture " + texture + " --extent 1e4",
         "texsplat: error: --extent: footprint texture: extent 10000 must be in (0, 8] voxels\n"},
        {"kernel --json --texture " + texture + " --extent 0",
         "texsplat: error: --extent: footprint texture: extent 0 must be in (0, 8] voxels\n"},
        {"kernel --json --kernel optimized --spacing 10,10,10 --texture " + texture,
         "texsplat: error: footprint texture: kernel support 15.5623 must be at most 8 voxels "
         "to measure the layer ripple\n"},
        {"kernel --texture /nonexistent-directory/t.pfm",
         "texsplat: error: /nonexistent-directory/t.pfm: cannot create a file in directory "
         "/nonexistent-directory: No such file or directory\n"},
        {"kernel --json --support 2",
         "texsplat: error: --support: needs --kernel optimized|gaussian or --optimize with "
         "--json (the paper's kernel has its own support)\n"},
    };
    for (const auto& badCase : cases) {
        const auto output = runTexsplat(badCase.arguments);
        EXPECT_EQ(output.exitCode, 1) << badCase.arguments;
        EXPECT_EQ(output.standardError, badCase.message) << badCase.arguments;
        // Every error comes before any result is printed.
        EXPECT_EQ(output.standardOutput, "") << badCase.arguments;
        EXPECT_FALSE(std::filesystem::exists(texture)) << badCase.arguments;
    }
    const auto unknownKernel = runTexsplat("kernel --kernel foo");
    EXPECT_NE(unknownKernel.exitCode, 0);
    EXPECT_NE(unknownKernel.standardError.find("--kernel: foo not in {paper,optimized,gaussian}"),
              std::string::npos);
    const auto badResolution = runTexsplat("kernel --texture x.pfm --resolution 1");
    EXPECT_NE(badResolution.exitCode, 0);
    EXPECT_NE(badResolution.standardError.find("--resolution"), std::string::npos);
}
