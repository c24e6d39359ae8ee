#include "RunCommand.h"

#include "nodes/image/ImageIo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using texsplat::image::Image;
using texsplat::test::runTexsplat;

namespace {

class RenderCommandTest : public texsplat::test::ScratchDirectoryTest {
protected:
    // A small scene file: a 12^3 blob as texture splats, no camera.
    std::string writeScene(const std::string& extra = "") const {
        const std::string scene = path("blob.iv");
        std::ofstream(scene) << "#Inventor V2.1 ascii\nSeparator {\n" << extra
                             << "TransferFunction { preset HOT range 0 1.2 opacities [ 0, 4 ] "
                                "opacityValues [ 0, 1 ] }\n"
                                "VolumeData { source BLOB resolution 12 12 12 }\n"
                                "TextureSplat { }\n}\n";
        return scene;
    }

    // Expects a failure with exactly `message` and no image left behind.
    void expectError(const std::string& arguments, const std::string& message,
                     const std::string& output) const {
        const auto result = runTexsplat("render " + arguments);
        EXPECT_EQ(result.exitCode, 1) << result.standardError;
        EXPECT_EQ(result.standardError, "texsplat: error: " + message + "\n");
        EXPECT_FALSE(fs::exists(output));
    }
};

TEST_F(RenderCommandTest, rendersTheDefaultSceneAndReportsItsTimes) {
    const std::string output = path("default.png");
    const auto result = runTexsplat("render -o " + output + " --size 48x32 --time-report");
    ASSERT_EQ(result.exitCode, 0) << result.standardError;
    for (const char* phase : {"read", "context", "load", "classify", "order", "upload", "draw",
                              "read back", "write", "splats "}) {
        EXPECT_NE(result.standardOutput.find(phase), std::string::npos) << phase;
    }
    // The default scene has no camera: framing it loads the tornado, which counts as load.
    const std::size_t load = result.standardOutput.find("  load ");
    ASSERT_NE(load, std::string::npos);
    double loadSeconds = -1.0;
    double framingSeconds = -1.0;
    ASSERT_EQ(std::sscanf(result.standardOutput.c_str() + load,
                          " load %lf (%lf of it while framing the scene)", &loadSeconds,
                          &framingSeconds),
              2)
        << result.standardOutput;
    EXPECT_GT(framingSeconds, 0.0);
    EXPECT_GE(loadSeconds, framingSeconds);
    const Image image = texsplat::image::readImage(output);
    EXPECT_EQ(image.width(), 48);
    EXPECT_EQ(image.height(), 32);
    const Image::Statistics statistics = image.statistics();
    EXPECT_EQ(statistics.nonFinitePixels, 0u);
    EXPECT_GT(statistics.maximum.r, 0.1);
    EXPECT_EQ(statistics.minimum.a, 1.0); // composited over opaque black
}

TEST_F(RenderCommandTest, aSceneWithItsOwnCameraIsNotFramed) {
    const std::string output = path("camera.png");
    const auto result = runTexsplat("render " + writeScene("PerspectiveCamera { }\n") + " -o " +
                                    output + " --size 16x16 --time-report");
    ASSERT_EQ(result.exitCode, 0) << result.standardError;
    EXPECT_NE(result.standardOutput.find("  load "), std::string::npos);
    EXPECT_EQ(result.standardOutput.find("framing"), std::string::npos);
}

TEST_F(RenderCommandTest, rendersASceneFileToExrWithDepthAndCameraOptions) {
    if (!texsplat::image::isExrSupported()) {
        GTEST_SKIP() << "built without OpenEXR";
    }
    const std::string output = path("blob.exr");
    const auto result = runTexsplat("render " + writeScene() + " -o " + output +
                                    " --size 32x32 --camera orthographic --direction 1,0,0");
    ASSERT_EQ(result.exitCode, 0) << result.standardError;
    const Image image = texsplat::image::readImage(output);
    const Image::Statistics statistics = image.statistics();
    EXPECT_EQ(statistics.nonFinitePixels, 0u);
    EXPECT_GT(statistics.maximum.r, 0.1);
    EXPECT_EQ(statistics.minimum.a, 0.0); // the EXR keeps the layer's own alpha
    // Z is window-space depth; splats do not write it, so a volume alone leaves 1 everywhere.
    ASSERT_TRUE(image.hasDepth());
    for (const float depth : image.depths()) {
        ASSERT_EQ(depth, 1.0f);
    }
    // The default scene's fibers are opaque: their depth lies in [0, 1), the rest stays 1.
    const std::string fibers = path("default.exr");
    ASSERT_EQ(runTexsplat("render -o " + fibers + " --size 48x32").exitCode, 0);
    const Image withFibers = texsplat::image::readImage(fibers);
    const std::vector<float>& depths = withFibers.depths();
    ASSERT_EQ(depths.size(), 48u * 32u);
    const auto [nearest, farthest] = std::minmax_element(depths.begin(), depths.end());
    EXPECT_GE(*nearest, 0.0f);
    EXPECT_LT(*nearest, 1.0f);
    EXPECT_EQ(*farthest, 1.0f);
}

TEST_F(RenderCommandTest, raycastRendersTheSameViewWithoutGl) {
    const std::string scene = writeScene();
    const std::string gl = path("gl.png");
    const std::string reference = path("raycast.png");
    const std::string options = " --size 32x24 --camera orthographic --direction 1,0.3,-0.2";
    ASSERT_EQ(runTexsplat("render " + scene + " -o " + gl + options).exitCode, 0);
    const auto result =
        runTexsplat("render " + scene + " -o " + reference + options + " --raycast --time-report");
    ASSERT_EQ(result.exitCode, 0) << result.standardError;
    EXPECT_NE(result.standardOutput.find("ray cast"), std::string::npos);
    EXPECT_EQ(result.standardOutput.find("context"), std::string::npos); // no GL context made
    const Image splats = texsplat::image::readImage(gl);
    const Image rayCast = texsplat::image::readImage(reference);
    ASSERT_EQ(rayCast.width(), 32);
    ASSERT_EQ(rayCast.height(), 24);
    const Image::Statistics statistics = rayCast.statistics();
    EXPECT_EQ(statistics.nonFinitePixels, 0u);
    EXPECT_GT(statistics.maximum.r, 0.1);
    EXPECT_EQ(statistics.minimum.a, 1.0);
    // The same blob from the same camera: the splats approximate the reference closely.
    double difference = 0.0;
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 32; ++x) {
            const glm::vec4 a = splats.pixel(x, y);
            const glm::vec4 b = rayCast.pixel(x, y);
            difference += std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
        }
    }
    EXPECT_LT(difference / (32 * 24 * 3), 0.02);
}

TEST_F(RenderCommandTest, reportsBadInputsAndWritesNothing) {
    const std::string png = path("out.png");
    expectError("-o " + png + " --size 64", "--size: expected WxH with whole numbers from 1 to "
                                            "16384, got '64'", png);
    expectError("-o " + png + " --size 0x10", "--size: expected WxH with whole numbers from 1 to "
                                              "16384, got '0x10'", png);
    const std::string tif = path("out.tif");
    expectError("-o " + tif, tif + ": unknown image extension '.tif' (supported: .png, .exr)", tif);
    expectError("-o " + png + " --camera fisheye",
                "--camera: expected 'perspective' or 'orthographic', got 'fisheye'", png);
    expectError("-o " + png + " --direction 0,0,0",
                "--direction: expected three numbers x,y,z not all zero, got '0,0,0'", png);
    const std::string withCamera = writeScene("PerspectiveCamera { }\n");
    expectError(withCamera + " -o " + png + " --direction 1,0,0",
                "--direction/--camera: the scene has its own camera (PerspectiveCamera); they "
                "frame scenes without one",
                png);
    // A grid with no finite voxel would render as an empty picture that hides the bad input.
    std::string nanVoxels = "texsplat-raw 1\ndims 2 2 2\ntype float32\ndata\n";
    const float nan = std::nanf("");
    for (int voxel = 0; voxel < 8; ++voxel) {
        nanVoxels.append(reinterpret_cast<const char*>(&nan), sizeof nan);
    }
    const std::string raw = write("nan.raw", nanVoxels);
    const std::string nanScene = write("nan.iv", "#Inventor V2.1 ascii\nSeparator {\n"
                                                 "VolumeData { source FILE_RAW fileName \"" +
                                                     raw + "\" }\nTextureSplat { }\n}\n");
    expectError(nanScene + " -o " + png,
                "VolumeData: " + raw + ": all 8 voxels are NaN or infinite; nothing to draw", png);
    const auto missing = runTexsplat("render " + path("missing.iv") + " -o " + png);
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.standardError.find(path("missing.iv")), std::string::npos);
    EXPECT_FALSE(fs::exists(png));
}

} // namespace
