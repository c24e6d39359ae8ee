#include "RunCommand.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace fs = std::filesystem;
using texsplat::test::runTexsplat;

namespace {

class BenchCommandTest : public texsplat::test::ScratchDirectoryTest {
protected:
    // The parts between separators; a trailing empty part counts for fields, not for lines.
    static std::vector<std::string> split(const std::string& text, char separator) {
        std::vector<std::string> parts;
        std::istringstream stream(text);
        std::string part;
        while (std::getline(stream, part, separator))
            parts.push_back(part);
        if (separator == ',' && !text.empty() && text.back() == separator)
            parts.emplace_back();
        return parts;
    }
};

TEST_F(BenchCommandTest, printsTheTableAndWritesCsvAndPlot) {
    const auto output =
        runTexsplat("bench --dataset ml8 --size 32x24 --repeat 1 --backend gl --method "
                    "texture,texture-gaussian,polygon,texture@0.5 --csv " +
                    path("bench.csv") + " --plot " + path("bench.svg"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    const std::string& text = output.standardOutput;
    EXPECT_NE(text.find("dataset     size      method             backend    splats   fragments  "
                        "ceil frags  frame ms   draw ms   ceil ms frame/c  draw/c   ref RMSE "
                        "ref PSNR  full RMSE full PSNR frame/tex   vs gl\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("ml8         32x24     texture            gl "), std::string::npos)
        << text;
    EXPECT_NE(text.find("ml8         32x24     polygon            gl "), std::string::npos)
        << text;

    const std::vector<std::string> lines = split(read(path("bench.csv")), '\n');
    ASSERT_EQ(lines.size(), 5u) << read(path("bench.csv"));
    EXPECT_EQ(lines[0], "dataset,width,height,method,full_quality,splats,fragments,"
                        "ceiling_fragments,frame_ms,load_ms,classify_ms,order_ms,upload_ms,"
                        "draw_ms,read_back_ms,ceiling_ms,frame_ratio,draw_ratio,reference_rmse,"
                        "reference_psnr,full_rmse,full_psnr,full_frame_ratio,backend,"
                        "gl_frame_ratio");
    const std::vector<std::string> methods = {"texture", "texture-gaussian", "polygon",
                                              "texture@0.5"};
    for (std::size_t row = 1; row < lines.size(); ++row) {
        const std::vector<std::string> fields = split(lines[row], ',');
        ASSERT_EQ(fields.size(), 25u) << lines[row];
        EXPECT_EQ(fields[0], "ml8");
        EXPECT_EQ(fields[23], "gl");
        EXPECT_EQ(fields[24], "1");
        EXPECT_EQ(fields[1], "32");
        EXPECT_EQ(fields[2], "24");
        EXPECT_EQ(fields[3], methods[row - 1]);
        EXPECT_EQ(fields[4], row == 1 ? "1" : "0");
        EXPECT_GT(std::stoull(fields[5]), 0u) << "splats";
        EXPECT_GT(std::stoull(fields[6]), 0u) << "fragments";
        EXPECT_GT(std::stoull(fields[7]), 0u) << "ceiling fragments";
        for (const int column : {8, 15, 16, 17}) { // frame, ceiling, both ratios
            const double value = std::stod(fields[static_cast<std::size_t>(column)]);
            EXPECT_TRUE(std::isfinite(value) && value > 0.0) << lines[0] << "\n" << lines[row];
        }
        const double referenceRmse = std::stod(fields[18]);
        EXPECT_TRUE(std::isfinite(referenceRmse) && referenceRmse >= 0.0) << lines[row];
        if (row == 1) {
            EXPECT_EQ(fields[20], "0") << "the full-quality image against itself";
            EXPECT_EQ(fields[21], "inf");
        } else {
            EXPECT_GT(std::stod(fields[20]), 0.0) << lines[row];
        }
    }
    // The octree cut of half the splats draws about half of them.
    const auto cutSplats = std::stod(split(lines[4], ',')[5]);
    const auto fullSplats = std::stod(split(lines[1], ',')[5]);
    EXPECT_LE(cutSplats, 0.5 * fullSplats + 1.0);
    const std::string svg = read(path("bench.svg"));
    EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    EXPECT_NE(svg.find("RMSE against the ray-cast reference"), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST_F(BenchCommandTest, timesVectorAndCombinedSplatsAgainstTextureSplatsInTheSameRun) {
    const auto output = runTexsplat("bench --dataset tornado10 --size 32x32 --repeat 1 "
                                    "--backend gl --method texture,vector,combined "
                                    "--no-reference --csv " +
                                    path("bench.csv"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    const std::vector<std::string> lines = split(read(path("bench.csv")), '\n');
    ASSERT_EQ(lines.size(), 4u);
    const std::vector<std::string> texture = split(lines[1], ',');
    EXPECT_EQ(texture[22], "1") << "the full-quality method against itself";
    for (const std::size_t row : {2u, 3u}) {
        const std::vector<std::string> fields = split(lines[row], ',');
        EXPECT_EQ(fields[3], row == 2 ? "vector" : "combined");
        EXPECT_GT(std::stoull(fields[5]), 0u) << "splats";
        const double ratio = std::stod(fields[22]);
        EXPECT_TRUE(std::isfinite(ratio) && ratio > 0.0) << lines[row];
        EXPECT_GT(std::stod(fields[20]), 0.0) << "marks change the image";
    }
}

TEST_F(BenchCommandTest, timesShadingAgainstTheUnshadedSplatsInTheSameRun) {
    const auto output = runTexsplat("bench --dataset ml16 --size 32x32 --repeat 2 "
                                    "--backend cpu,gl --method texture,texture+shade,"
                                    "texture+shade@0.5 --csv " +
                                    path("bench.csv"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    const std::vector<std::string> lines = split(read(path("bench.csv")), '\n');
    ASSERT_EQ(lines.size(), 7u);
    for (std::size_t row = 1; row < lines.size(); ++row) {
        const std::vector<std::string> fields = split(lines[row], ',');
        const bool shaded = fields[3] != "texture";
        EXPECT_EQ(fields[3], row <= 2 ? "texture" : row <= 4 ? "texture+shade"
                                                               : "texture+shade@0.5");
        // The cost: frame time over the unshaded texture splats' in the same run.
        const double ratio = std::stod(fields[22]);
        EXPECT_TRUE(std::isfinite(ratio) && ratio > 0.0) << lines[row];
        // Shaded splats against the reference shaded per sample: close.
        EXPECT_GT(std::stod(fields[19]), 25.0) << lines[row];
        EXPECT_EQ(fields[20].empty(), shaded) << "no image comparison across shading";
    }
}

TEST_F(BenchCommandTest, skipsTheReferenceWhenAsked) {
    const auto output = runTexsplat("bench --dataset blob6 --size 16x16 --repeat 1 "
                                    "--backend gl --method texture,polygon --no-reference --csv " +
                                    path("bench.csv"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_EQ(output.standardError.find("reference"), std::string::npos) << output.standardError;
    const std::vector<std::string> lines = split(read(path("bench.csv")), '\n');
    ASSERT_EQ(lines.size(), 3u);
    const std::vector<std::string> fields = split(lines[2], ',');
    ASSERT_EQ(fields.size(), 25u) << lines[2];
    EXPECT_EQ(fields[18], "") << "no reference RMSE";
    EXPECT_EQ(fields[19], "") << "no reference PSNR";
    EXPECT_GT(std::stod(fields[20]), 0.0) << "the polygon against the texture splats";
}

TEST_F(BenchCommandTest, timesBothBackendsInOneRunAgainstTheSameReference) {
    const auto output = runTexsplat("bench --dataset ml12 --size 40x32 --repeat 1 --backend "
                                    "cpu,gl --method texture,polygon --csv " +
                                    path("bench.csv"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("texsplat bench: CPU ("), std::string::npos)
        << output.standardOutput;
    const std::vector<std::string> lines = split(read(path("bench.csv")), '\n');
    ASSERT_EQ(lines.size(), 5u) << read(path("bench.csv"));
    // Rows: texture cpu, texture gl, polygon cpu, polygon gl.
    std::vector<std::vector<std::string>> rows;
    for (std::size_t row = 1; row < lines.size(); ++row) {
        rows.push_back(split(lines[row], ','));
        ASSERT_EQ(rows.back().size(), 25u) << lines[row];
    }
    for (const std::size_t row : {0u, 2u}) {
        EXPECT_EQ(rows[row][23], "cpu");
        EXPECT_EQ(rows[row + 1][23], "gl");
        EXPECT_EQ(rows[row][5], rows[row + 1][5]) << "both backends draw the same splats";
        EXPECT_EQ(rows[row][6], "0") << "no GL fragment query on the CPU";
        EXPECT_EQ(rows[row][15], "") << "no fill-rate ceiling on the CPU";
        const double ratio = std::stod(rows[row][24]);
        EXPECT_TRUE(std::isfinite(ratio) && ratio > 0.0) << lines[row + 1];
        // The same error against the reference, to well within 1 dB.
        EXPECT_NEAR(std::stod(rows[row][19]), std::stod(rows[row + 1][19]), 1.0)
            << lines[row + 1] << "\n" << lines[row + 2];
    }
    EXPECT_EQ(rows[0][21], "inf") << "each backend's full-quality image against itself";
    EXPECT_EQ(rows[1][21], "inf");
}

TEST_F(BenchCommandTest, reportsBadOptionsByTheirExactMessage) {
    auto output = runTexsplat("bench --dataset ml8,foo --size 16x16");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardOutput, "");
    EXPECT_EQ(output.standardError,
              "texsplat: error: --dataset: unknown dataset 'foo' (expected ml<N>, tornado<N> or "
              "blob<N> with N from 2 to 1024, e.g. ml41, ml128, tornado128, blob256)\n");
    output = runTexsplat("bench --dataset ml8 --method texture@1.5");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError,
              "texsplat: error: --method: unknown method 'texture@1.5' (expected texture, "
              "texture-gaussian, polygon, vector or combined, optionally with +shade and "
              "@FRACTION, e.g. texture+shade@0.1)\n");
    output = runTexsplat("bench --dataset tornado8 --method vector+shade");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_NE(output.standardError.find("unknown method 'vector+shade'"), std::string::npos)
        << "marks are not shaded: " << output.standardError;
    output = runTexsplat("bench --dataset ml8 --backend cpu,metal");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError,
              "texsplat: error: --backend: expected cpu, gl or auto, got 'metal'\n");
    output = runTexsplat("bench --dataset tornado8,ml8 --method texture,vector");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: --method: vector draws vectors, but "
                                    "dataset ml8 is scalar (use tornado<N>)\n");
    output = runTexsplat("bench --dataset ml8 --size 16by16");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: --size: expected WxH with whole numbers "
                                    "from 1 to 16384, got '16by16'\n");
    output = runTexsplat("bench --dataset ml8 --camera fisheye");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: --camera: expected 'perspective' or "
                                    "'orthographic', got 'fisheye'\n");
}

TEST_F(BenchCommandTest, theDatasetsCanBeSeenThroughAnOrthographicCamera) {
    // As VTK's ray caster is compared (issue 11): the same data through either camera. The
    // orthographic view of the same volume draws the same splats, and its error against its
    // own ray-cast reference stays small.
    const auto perspective = runTexsplat(
        "bench --dataset ml16 --size 48x48 --repeat 1 --backend cpu --method texture --csv " +
        path("perspective.csv"));
    const auto orthographic = runTexsplat(
        "bench --dataset ml16 --size 48x48 --repeat 1 --backend cpu --method texture "
        "--camera orthographic --csv " +
        path("orthographic.csv"));
    ASSERT_EQ(perspective.exitCode, 0) << perspective.standardError;
    ASSERT_EQ(orthographic.exitCode, 0) << orthographic.standardError;
    EXPECT_NE(perspective.standardOutput.find(", perspective camera;"), std::string::npos)
        << perspective.standardOutput;
    EXPECT_NE(orthographic.standardOutput.find(", orthographic camera;"), std::string::npos)
        << orthographic.standardOutput;
    const auto row = [&](const std::string& file) {
        const std::vector<std::string> lines = split(read(path(file)), '\n');
        EXPECT_EQ(lines.size(), 2u);
        return lines.size() == 2u ? split(lines[1], ',') : std::vector<std::string>(25);
    };
    const std::vector<std::string> fromPerspective = row("perspective.csv");
    const std::vector<std::string> fromOrthographic = row("orthographic.csv");
    EXPECT_EQ(fromOrthographic[5], fromPerspective[5]) << "splats";
    EXPECT_GT(std::stod(fromOrthographic[19]), 30.0) << "PSNR against the ray-cast reference";
    EXPECT_NE(fromOrthographic[18], fromPerspective[18]) << "another view, another error";
}

TEST_F(BenchCommandTest, plotMustBeSvgAndIsCheckedBeforeTheRun) {
    const auto output =
        runTexsplat("bench --dataset ml8 --size 32x24 --repeat 1 --plot " + path("bench.png"));
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardOutput, "");
    EXPECT_EQ(output.standardError, "texsplat: error: " + path("bench.png") +
                                        ": unknown plot extension '.png' (supported: .svg)\n");
    EXPECT_FALSE(fs::exists(path("bench.png")));
}

// A user's scene: a small tornado without a camera, so bench frames it as render does.
std::string writeSmallScene(const std::string& file) {
    std::ofstream(file) << "#Inventor V2.1 ascii\n"
                           "Separator {\n"
                           "    TransferFunction { preset BROWNS range 0 0.32 opacityValues [ 0, "
                           "0.35, 1 ] opacities [ 0, 0, 20 ] }\n"
                           "    VolumeData { source TORNADO resolution 16 16 16 }\n"
                           "    TextureSplat { }\n"
                           "}\n";
    return file;
}

TEST_F(BenchCommandTest, measuresAScenesOwnSplatNodesAtEachBudget) {
    const std::string scene = writeSmallScene(path("small.iv"));
    const auto output = runTexsplat("bench " + scene + " --size 32x32 --repeat 1 --budgets "
                                    "1,0.5,0.1 --csv " + path("bench.csv"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("texsplat bench: CPU ("), std::string::npos)
        << output.standardOutput;
    const std::vector<std::string> lines = split(read(path("bench.csv")), '\n');
    ASSERT_EQ(lines.size(), 4u) << read(path("bench.csv"));
    std::vector<std::vector<std::string>> rows;
    for (std::size_t row = 1; row < lines.size(); ++row) {
        rows.push_back(split(lines[row], ','));
        ASSERT_EQ(rows.back().size(), 25u) << lines[row];
        EXPECT_EQ(rows.back()[0], "small.iv");
        EXPECT_EQ(rows.back()[23], "cpu") << "a scene is measured on the CPU backend";
        EXPECT_GT(std::stod(rows.back()[19]), 0.0) << "error against the ray-cast reference";
    }
    EXPECT_EQ(rows[0][3], "scene");
    EXPECT_EQ(rows[1][3], "scene@0.5");
    EXPECT_EQ(rows[2][3], "scene@0.1");
    EXPECT_EQ(rows[0][4], "1") << "full resolution is the full-quality image";
    EXPECT_EQ(rows[0][21], "inf");
    const std::size_t full = std::stoul(rows[0][5]);
    EXPECT_LE(std::stoul(rows[1][5]), (full + 1) / 2);
    EXPECT_GT(std::stoul(rows[1][5]), std::stoul(rows[2][5]));
    EXPECT_LE(std::stoul(rows[2][5]), full / 10 + 1);
    // Fewer splats, more error against the full-resolution image.
    EXPECT_GT(std::stod(rows[2][20]), std::stod(rows[1][20])) << lines[2] << "\n" << lines[3];
    EXPECT_GT(std::stod(rows[1][20]), 0.0);
}

TEST_F(BenchCommandTest, timesTheFrameAfterATransferFunctionEditAgainstAFreshScene) {
    const std::string scene = writeSmallScene(path("small.iv"));
    const auto output =
        runTexsplat("bench " + scene + " --size 32x32 --transfer-edit 200 --threads 1");
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    const std::vector<std::string> lines = split(output.standardOutput, '\n');
    ASSERT_EQ(lines.size(), 6u) << output.standardOutput;
    EXPECT_EQ(lines[0].rfind("texsplat bench --transfer-edit: " + scene + ", 32x32, CPU (", 0),
              0u)
        << lines[0];
    // Full resolution and 200 splats, each after both edits; no edit rebuilds the value ranges.
    const std::vector<std::string> starts{"opacities x 0.5     full", "range from 30 %     full",
                                          "opacities x 0.5      200", "range from 30 %      200"};
    for (std::size_t row = 0; row < starts.size(); ++row) {
        EXPECT_EQ(lines[row + 2].rfind(starts[row], 0), 0u) << lines[row + 2];
        EXPECT_EQ(lines[row + 2].back(), '0') << lines[row + 2];
    }
    // --images writes the frames it timed, exact and preview, after each edit at each budget.
    const auto withImages = runTexsplat("bench " + scene +
                                        " --size 32x32 --transfer-edit 200 --threads 1 --images " +
                                        path(""));
    ASSERT_EQ(withImages.exitCode, 0) << withImages.standardError;
    for (const std::string edit : {"opacities-half", "range-from-30"}) {
        for (const std::string budget : {"full", "200"}) {
            for (const std::string kind : {"exact", "preview"}) {
                const std::string image = path(edit + "-" + budget + "-" + kind + ".png");
                EXPECT_TRUE(std::filesystem::is_regular_file(image)) << image;
            }
        }
    }
    const auto noFolder = runTexsplat("bench " + scene + " --transfer-edit 200 --images " +
                                      path("missing"));
    EXPECT_EQ(noFolder.exitCode, 1);
    EXPECT_NE(noFolder.standardError.find("cannot write the images: folder '" + path("missing") +
                                          "' does not exist"),
              std::string::npos)
        << noFolder.standardError;
    const auto noEditForImages = runTexsplat("bench " + scene + " --images " + path(""));
    EXPECT_EQ(noEditForImages.exitCode, 1);
    EXPECT_EQ(noEditForImages.standardError,
              "texsplat: error: --images: only with --transfer-edit or --legibility (it writes the "
              "frames they measure)\n");
    auto noEdit = runTexsplat("bench --transfer-edit 200");
    EXPECT_EQ(noEdit.exitCode, 1);
    EXPECT_EQ(noEdit.standardError, "texsplat: error: --transfer-edit: only with a SCENE (its "
                                    "transfer functions are edited)\n");
}

TEST_F(BenchCommandTest, reportsBadSceneOptionsByTheirExactMessage) {
    const std::string scene = writeSmallScene(path("small.iv"));
    auto output = runTexsplat("bench " + scene + " --budgets 1,0");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: --budgets: expected fractions in (0, 1], "
                                    "e.g. 1,0.1,0.01, got '1,0'\n");
    output = runTexsplat("bench " + scene + " --dataset ml8");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: --dataset/--method: a SCENE is measured "
                                    "with its own volumes and splat nodes, at --budgets\n");
    output = runTexsplat("bench --dataset ml8 --budgets 0.5");
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError,
              "texsplat: error: --budgets/--direction/--azimuth/--elevation/--zoom: only with a "
              "SCENE (the datasets have their own views; --method sets budgets)\n");
}

} // namespace
