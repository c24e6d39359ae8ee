#include "RunCommand.h"

#include "nodes/image/ImageIo.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
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
                                    " --size 32x32 --camera orthographic --direction 1,0,0 "
                                    "--background transparent");
    ASSERT_EQ(result.exitCode, 0) << result.standardError;
    const Image image = texsplat::image::readImage(output);
    const Image::Statistics statistics = image.statistics();
    EXPECT_EQ(statistics.nonFinitePixels, 0u);
    EXPECT_GT(statistics.maximum.r, 0.1);
    EXPECT_EQ(statistics.minimum.a, 0.0); // a transparent background: the layer's own alpha
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
    expectError("-o " + png + " --up 0,0,0",
                "--up: expected three numbers x,y,z not all zero, got '0,0,0'", png);
    expectError("-o " + png + " --direction 0,0,-1 --up 0,0,2",
                "default scene: cannot frame it: the up direction is parallel to the viewing "
                "direction: no up can be seen; give one across the view",
                png);
    const std::string withCamera = writeScene("PerspectiveCamera { }\n");
    expectError(withCamera + " -o " + png + " --up 0,0,1",
                "--up: 0,0,1: the up direction is parallel to the viewing direction: no up can "
                "be seen; give one across the view",
                png);
    expectError("-o " + png + " --zoom 0", "--zoom: expected a magnification > 0, got '0'", png);
    expectError("-o " + png + " --azimuth east", "--azimuth: expected degrees, got 'east'", png);
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
                nanScene + ":3:1: VolumeData: " + raw +
                    ": all 8 voxels are NaN or infinite; nothing to draw",
                png);
    const auto missing = runTexsplat("render " + path("missing.iv") + " -o " + png);
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.standardError.find(path("missing.iv")), std::string::npos);
    EXPECT_FALSE(fs::exists(png));
}

// A blob whose emission grows with the scene's time: every frame of an animation differs.
// Speed 2, a power of two, keeps the engine exact: the queue's float times differ exactly in
// double, and doubling them rounds nothing, so the emission at a time does not depend on the
// steps that led there.
const std::string kGlowingBlob = "#Inventor V2.1 ascii\nSeparator {\n"
                                 "TransferFunction { preset HOT range 0 1.2 opacities [ 0, 4 ] "
                                 "opacityValues [ 0, 1 ]\n"
                                 "  emission = ElapsedTime { speed 2 } . timeOut }\n"
                                 "VolumeData { source BLOB resolution 12 12 12 }\n"
                                 "TextureSplat { }\n}\n";

TEST_F(RenderCommandTest, framesFollowASimulatedClockAndEveryRunWritesTheSameBytes) {
    const std::string scene = write("glowing.iv", kGlowingBlob);
    const std::string options = " --size 24x24 --frames 4 --fps 2";
    const auto first = runTexsplat("render " + scene + options + " -o " + path("a%02d.png"));
    ASSERT_EQ(first.exitCode, 0) << first.standardError;
    EXPECT_EQ(first.standardOutput, "");
    EXPECT_EQ(first.standardError, "frame 1/4 (t = 0 s): " + path("a00.png") + "\n" +
                                       "frame 2/4 (t = 0.5 s): " + path("a01.png") + "\n" +
                                       "frame 3/4 (t = 1 s): " + path("a02.png") + "\n" +
                                       "frame 4/4 (t = 1.5 s): " + path("a03.png") + "\n");
    EXPECT_FALSE(fs::exists(path("a04.png")));
    const auto second = runTexsplat("render " + scene + options + " -o " + path("b%02d.png"));
    ASSERT_EQ(second.exitCode, 0) << second.standardError;
    double lastMean = -1.0;
    for (int frame = 0; frame < 4; ++frame) {
        const std::string name = "0" + std::to_string(frame) + ".png";
        const std::string bytes = read(path("a" + name));
        ASSERT_FALSE(bytes.empty()) << name;
        EXPECT_EQ(bytes, read(path("b" + name))) << "frame " << frame << " differs between runs";
        // The emission grows with time: each frame is brighter than the one before.
        const double mean = texsplat::image::readImage(path("a" + name)).statistics().mean.r;
        EXPECT_GT(mean, lastMean + 0.01) << "frame " << frame;
        lastMean = mean;
    }
    // Frame 0 is the scene at time 0: what a plain render (no --frames) draws.
    const std::string still = path("still.png");
    ASSERT_EQ(runTexsplat("render " + scene + " --size 24x24 -o " + still).exitCode, 0);
    EXPECT_EQ(read(still), read(path("a00.png")));
}

// What makes a periodic animation repeat is that a frame is a function of its scene time alone,
// not of the frames rendered before it; that is checked here: frame k at 2 fps and frame 2k at
// 4 fps show the same time k/2 after different histories, and are the same bytes.
TEST_F(RenderCommandTest, aFrameDependsOnlyOnItsSceneTime) {
    const std::string scene = write("glowing.iv", kGlowingBlob);
    ASSERT_EQ(runTexsplat("render " + scene + " --size 24x24 --frames 3 --fps 2 -o " +
                          path("slow%d.png"))
                  .exitCode,
              0);
    ASSERT_EQ(runTexsplat("render " + scene + " --size 24x24 --frames 5 --fps 4 -o " +
                          path("fast%d.png"))
                  .exitCode,
              0);
    for (int frame = 0; frame < 3; ++frame) {
        const std::string slow = read(path("slow" + std::to_string(frame) + ".png"));
        ASSERT_FALSE(slow.empty());
        EXPECT_EQ(slow, read(path("fast" + std::to_string(2 * frame) + ".png"))) << frame;
    }
    EXPECT_NE(read(path("fast1.png")), read(path("fast2.png")));
}

// Vector splats cycle through the rows of their table: with ElapsedTime speed 0.5 the phase
// (in cycles) repeats every 2 s, 8 frames at 4 fps, and so does the image, bit for bit.
TEST_F(RenderCommandTest, anAnimationWhosePhasePeriodIsPFramesRepeatsAfterPFrames) {
    const std::string scene = write(
        "flow.iv", "#Inventor V2.1 ascii\nSeparator {\n"
                   "TransferFunction { range 0 0.32 opacities [ 0, 60 ] }\n"
                   "VolumeData { source TORNADO resolution 10 10 10 }\n"
                   "VectorSplat { phase = ElapsedTime { speed 0.5 } . timeOut }\n}\n");
    ASSERT_EQ(runTexsplat("render " + scene + " --size 32x32 --frames 10 --fps 4 -o " +
                          path("flow%d.png"))
                  .exitCode,
              0);
    EXPECT_EQ(read(path("flow0.png")), read(path("flow8.png")));
    EXPECT_EQ(read(path("flow1.png")), read(path("flow9.png")));
    for (int frame = 1; frame < 8; ++frame) {
        EXPECT_NE(read(path("flow0.png")), read(path("flow" + std::to_string(frame) + ".png")))
            << "frame " << frame << " of the period";
    }
}

TEST_F(RenderCommandTest, timeReportOfFramesGivesTotalsAndTheMeanPerFrame) {
    const auto result = runTexsplat("render " + write("glowing.iv", kGlowingBlob) +
                                    " --size 16x16 --frames 2 -o " + path("f%d.png") +
                                    " --time-report");
    ASSERT_EQ(result.exitCode, 0) << result.standardError;
    const std::string& report = result.standardOutput;
    EXPECT_EQ(report.rfind("time report (wall seconds; 2 frames: totals over the frames, then "
                           "the mean per frame):\n",
                           0),
              0u)
        << report;
    for (const char* phase : {"animate", "load", "draw", "write"}) {
        const std::size_t line = report.find(std::string("  ") + phase + " ");
        ASSERT_NE(line, std::string::npos) << phase;
        double total = -1.0;
        double mean = -1.0;
        ASSERT_EQ(std::sscanf(report.c_str() + line + 2 + std::strlen(phase), "%lf %lf per frame",
                              &total, &mean),
                  2)
            << report;
        EXPECT_NEAR(mean, total / 2, 1e-4) << phase;
    }
    EXPECT_NE(report.find("(all frames)"), std::string::npos);
    // A 24 fps default: the second frame is at 1/24 s.
    EXPECT_NE(result.standardError.find("frame 2/2 (t = 0.0416667 s): " + path("f1.png")),
              std::string::npos)
        << result.standardError;
}

TEST_F(RenderCommandTest, raycastRendersFramesToo) {
    const auto result = runTexsplat("render " + write("glowing.iv", kGlowingBlob) +
                                    " --size 8x8 --raycast --frames 2 --fps 1 -o " +
                                    path("ray%d.png"));
    ASSERT_EQ(result.exitCode, 0) << result.standardError;
    const std::string first = read(path("ray0.png"));
    ASSERT_FALSE(first.empty());
    EXPECT_NE(first, read(path("ray1.png")));
}

TEST_F(RenderCommandTest, aSingleImageNameIsAPatternOnlyWhenItHoldsOneFrameNumber) {
    const std::string scene = writeScene();
    // A frame pattern without --frames writes frame 0; any other name is used as it is.
    ASSERT_EQ(runTexsplat("render " + scene + " --size 8x8 -o " + path("one%03d.png")).exitCode,
              0);
    EXPECT_TRUE(fs::exists(path("one000.png")));
    ASSERT_EQ(runTexsplat("render " + scene + " --size 8x8 -o " + path("50%.png")).exitCode, 0);
    EXPECT_TRUE(fs::exists(path("50%.png")));
    ASSERT_EQ(runTexsplat("render " + scene + " --size 8x8 -o " + path("%%%-3d.png")).exitCode,
              0);
    EXPECT_TRUE(fs::exists(path("%0  .png")));
}

TEST_F(RenderCommandTest, reportsBadFrameOptionsBeforeAnyWork) {
    const std::string scene = writeScene();
    const std::string pattern = path("out%04d.png");
    const std::string first = path("out0000.png");
    const std::string png = path("out.png");
    expectError(scene + " --frames 3 -o " + png,
                "--frames 3 needs an output name with one %d-style frame number (e.g. "
                "out%04d.png), got '" +
                    png + "'",
                png);
    for (const char* frames : {"0", "-1", "x", "2.5", "1000001", "''"}) {
        expectError(scene + " --frames " + frames + " -o " + pattern,
                    std::string("--frames: expected a whole number from 1 to 1000000, got '") +
                        (std::string(frames) == "''" ? "" : frames) + "'",
                    first);
    }
    for (const char* fps : {"0", "-24", "nan", "inf", "24fps", "''"}) {
        expectError(scene + " --frames 2 --fps " + fps + " -o " + pattern,
                    std::string("--fps: expected a finite number of frames per second > 0, got '") +
                        (std::string(fps) == "''" ? "" : fps) + "'",
                    first);
    }
    expectError(scene + " --frames 3 --fps 1e-300 -o " + pattern,
                "--fps: at 1e-300 frames per second frame 2 would be at 2e+300 s, beyond the "
                "scene's time (a float)",
                first);
    for (const char* conversion : {"%s", "%.3d", "%ld", "%100d", "%+d", "%x"}) {
        const std::string name = path(std::string("out") + conversion + ".png");
        expectError(scene + " --frames 2 -o '" + name + "'",
                    "--output: '" + std::string(conversion) + "' in '" + name +
                        "' is not a frame number; use %d, %04d (4 digits, zero-padded) or %% "
                        "for a '%'",
                    first);
    }
    const std::string twice = path("out%d_%d.png");
    expectError(scene + " --frames 2 -o " + twice,
                "--output: '" + twice + "' has 2 %d-style numbers; a frame name needs exactly one",
                path("out0_0.png"));
    const std::string tif = path("out%04d.tif");
    expectError(scene + " --frames 2 -o " + tif,
                tif + ": unknown image extension '.tif' (supported: .png, .exr)",
                path("out0000.tif"));
}

TEST_F(RenderCommandTest, rendersWithEitherBackendAndNamesItInTheTimeReport) {
    const std::string scene = writeScene();
    const std::string options = " --size 40x30 --time-report";
    const auto cpu = runTexsplat("render " + scene + " -o " + path("cpu.png") + options +
                                 " --backend cpu --threads 3");
    ASSERT_EQ(cpu.exitCode, 0) << cpu.standardError;
    EXPECT_NE(cpu.standardOutput.find("  backend    CPU ("), std::string::npos) << cpu.standardOutput;
    EXPECT_NE(cpu.standardOutput.find(", 3 threads) (asked for)"), std::string::npos)
        << cpu.standardOutput;
    EXPECT_NE(cpu.standardOutput.find("  context       0.0000\n"), std::string::npos)
        << "no GL context for the CPU backend\n"
        << cpu.standardOutput;
    const auto gl =
        runTexsplat("render " + scene + " -o " + path("gl.png") + options + " --backend gl");
    ASSERT_EQ(gl.exitCode, 0) << gl.standardError;
    EXPECT_NE(gl.standardOutput.find("  backend    GL (EGL "), std::string::npos)
        << gl.standardOutput;
    // The same image to the PNG's 8 bits, but for rounding.
    const Image a = texsplat::image::readImage(path("cpu.png"));
    const Image b = texsplat::image::readImage(path("gl.png"));
    float largest = 0.0f;
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x < 40; ++x) {
            const glm::vec4 difference = glm::abs(a.pixel(x, y) - b.pixel(x, y));
            largest = std::max({largest, difference.r, difference.g, difference.b});
        }
    }
    EXPECT_LE(largest, 1.0f / 255.0f + 1e-6f);
    EXPECT_GT(a.statistics().maximum.r, 0.1);
    // auto: the CPU where EGL lists no GPU, on a software rasterizer or without GL, GL on a
    // GPU, and the report says which and why.
    const auto automatic =
        runTexsplat("render " + scene + " -o " + path("auto.png") + options);
    ASSERT_EQ(automatic.exitCode, 0) << automatic.standardError;
    const std::string& report = automatic.standardOutput;
    const bool software = report.find("(auto: GL is a software rasterizer (") != std::string::npos;
    const bool noGl = report.find("(auto: no GL context (") != std::string::npos;
    const bool device = report.find("(auto: GL device ") != std::string::npos;
    const bool noGpu = report.find("(auto: no GPU among EGL's devices)") != std::string::npos;
    EXPECT_EQ(software + noGl + device + noGpu, 1) << report;
    EXPECT_EQ(report.find("  backend    CPU (") != std::string::npos, software || noGl || noGpu)
        << report;
}

TEST_F(RenderCommandTest, vectorSplatsRenderOnTheCpuBackendAsOnGl) {
    const std::string scene =
        write("winds.iv", "#Inventor V2.1 ascii\nSeparator {\n"
                          "TransferFunction { range 0 0.32 opacities [ 0, 60 ] }\n"
                          "VolumeData { source TORNADO resolution 8 8 8 }\n"
                          "VectorSplat { operator BLEND markLength 4 }\n}\n");
    std::vector<Image> images;
    for (const char* backend : {"cpu", "gl"}) {
        const std::string output = path(std::string("winds-") + backend + ".png");
        const auto result = runTexsplat("render " + scene + " -o " + output +
                                        " --size 40x40 --backend " + backend);
        ASSERT_EQ(result.exitCode, 0) << backend << ": " << result.standardError;
        images.push_back(texsplat::image::readImage(output));
    }
    float largest = 0.0f;
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) {
            const glm::vec4 difference = glm::abs(images[0].pixel(x, y) - images[1].pixel(x, y));
            largest = std::max({largest, difference.r, difference.g, difference.b});
        }
    }
    EXPECT_GT(images[0].statistics().maximum.r, 0.05) << "marks drawn";
    // The PNGs' 8 bits.
    EXPECT_LE(largest, 3.0f / 255.0f);
}

TEST_F(RenderCommandTest, reportsBadBackendOptionsBeforeAnyWork) {
    const std::string scene = writeScene();
    const std::string output = path("out.png");
    expectError(scene + " -o " + output + " --backend vulkan",
                "--backend: expected cpu, gl or auto, got 'vulkan'", output);
    expectError(scene + " -o " + output + " --threads -1",
                "--threads: expected 0 (one per hardware thread) to 1024, got -1", output);
}

TEST_F(RenderCommandTest, pngAndExrShareTheBackgroundAndCompareSaysWhenTheyDoNot) {
    const std::string scene = writeScene();
    const std::string options = " --size 24x24 --camera orthographic";
    ASSERT_EQ(runTexsplat("render " + scene + " -o " + path("black.png") + options).exitCode, 0);
    ASSERT_EQ(runTexsplat("render " + scene + " -o " + path("clear.png") + options +
                          " --background transparent")
                  .exitCode,
              0);
    EXPECT_EQ(texsplat::image::readImage(path("black.png")).statistics().minimum.a, 1.0)
        << "opaque black by default";
    const Image clear = texsplat::image::readImage(path("clear.png"));
    EXPECT_LT(clear.statistics().minimum.a, 0.5) << "thin medium and empty corners show through";
    EXPECT_GT(clear.statistics().maximum.r, 0.05);
    if (texsplat::image::isExrSupported()) {
        ASSERT_EQ(runTexsplat("render " + scene + " -o " + path("black.exr") + options).exitCode,
                  0);
        EXPECT_EQ(texsplat::image::readImage(path("black.exr")).statistics().minimum.a, 1.0)
            << "EXR composited over the same black as PNG by default";
    }
    const auto compared = runTexsplat("compare " + path("black.png") + " " + path("clear.png"));
    EXPECT_EQ(compared.exitCode, 0) << compared.standardError;
    EXPECT_NE(compared.standardError.find(path("black.png") + " is opaque (alpha 1 everywhere) "
                                          "and " + path("clear.png") + " is not"),
              std::string::npos)
        << compared.standardError;
    expectError(scene + " -o " + path("bad.png") + " --background 1.5,0,0",
                "--background: expected black, white, transparent or r,g,b (0 to 1), got "
                "'1.5,0,0'",
                path("bad.png"));
}

TEST_F(RenderCommandTest, budgetOptionsSetEverySplatNodeWithoutEditingTheScene) {
    const auto splatsOf = [this](const std::string& options) {
        const auto result = runTexsplat("render " + writeScene() + " -o " + path("cut.png") +
                                        " --size 24x24 --time-report" + options);
        EXPECT_EQ(result.exitCode, 0) << result.standardError;
        std::size_t splats = 0;
        const std::size_t line = result.standardOutput.find("  splats ");
        EXPECT_NE(line, std::string::npos) << result.standardOutput;
        std::sscanf(result.standardOutput.c_str() + line, "  splats %zu", &splats);
        return splats;
    };
    const std::size_t full = splatsOf("");
    const std::size_t budget = splatsOf(" --max-splats 200");
    EXPECT_GT(full, 1000u);
    EXPECT_LE(budget, 200u);
    EXPECT_GT(budget, 0u);
    EXPECT_LT(splatsOf(" --error-threshold 0.5"), full);
    const std::string scene = writeScene();
    expectError(scene + " -o " + path("bad.png") + " --max-splats -5",
                "--max-splats: expected a whole number from 0 (no budget) to 999999999, got '-5'",
                path("bad.png"));
    expectError(scene + " -o " + path("bad.png") + " --error-threshold nan",
                "--error-threshold: expected a finite number >= 0 (0: full resolution), got 'nan'",
                path("bad.png"));
}

TEST_F(RenderCommandTest, cameraOptionsOrbitAndZoomAnyScenesCamera) {
    // A scene with its own camera looking at the blob from +z, at its focal point.
    const std::string scene = writeScene("PerspectiveCamera { position 0.5 0.5 3 "
                                         "focalDistance 2.5 }\n");
    const auto render = [&](const std::string& name, const std::string& options) {
        const auto result = runTexsplat("render " + scene + " -o " + path(name) +
                                        " --size 32x32 --backend cpu" + options);
        EXPECT_EQ(result.exitCode, 0) << options << ": " << result.standardError;
        return texsplat::image::readImage(path(name));
    };
    const auto difference = [](const Image& a, const Image& b) {
        double sum = 0.0;
        for (int y = 0; y < a.height(); ++y) {
            for (int x = 0; x < a.width(); ++x) {
                const glm::vec4 d = a.pixel(x, y) - b.pixel(x, y);
                sum += std::abs(d.r) + std::abs(d.g) + std::abs(d.b);
            }
        }
        return sum / (a.width() * a.height());
    };
    const Image front = render("front.png", "");
    const Image side = render("side.png", " --azimuth 90");
    const Image around = render("around.png", " --azimuth 360 --elevation 0");
    const Image sideByDirection = render("direction.png", " --direction -1,0,0");
    const Image zoomed = render("zoomed.png", " --zoom 2");
    EXPECT_GT(difference(front, side), 0.01) << "the blob is not round: a side view differs";
    EXPECT_LT(difference(front, around), 1e-3) << "a full turn comes back";
    EXPECT_LT(difference(side, sideByDirection), 1e-3)
        << "azimuth 90 from +z looks along -x, as --direction -1,0,0 at the same focal point";
    // Zoomed twice: the centre pixel's neighbourhood grows; the image's brightest values stay.
    EXPECT_GT(difference(front, zoomed), 0.01);
    EXPECT_GT(zoomed.statistics().mean.r, front.statistics().mean.r) << "more of the image is blob";
    // --up rolls the view about its direction: x up turns the picture a quarter
    // counter-clockwise.
    const Image rolled = render("rolled.png", " --up 1,0,0");
    double turned = 0.0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            // Looking along -z with +x up, +y points left and -y right: pixel (x, y) of the
            // front view (x along +x, y down along -y) is at (y, 31 - x) of the rolled one.
            const glm::vec4 d = front.pixel(x, y) - rolled.pixel(y, 31 - x);
            turned += std::abs(d.r) + std::abs(d.g) + std::abs(d.b);
        }
    }
    EXPECT_LT(turned / (32 * 32), 1e-3);
    EXPECT_GT(difference(front, rolled), 0.01) << "the blob is not round: the roll shows";
}

TEST_F(RenderCommandTest, cameraOptionTurnsTheScenesCameraIntoTheOtherKind) {
    // ParaView's parallel projection switch: the same view at the focal distance. A slab of
    // glow seen from +z looks the same through both cameras at its own depth.
    const std::string scene = writeScene("PerspectiveCamera { position 0.5 0.5 3 "
                                         "focalDistance 2.5 heightAngle 0.2 }\n");
    const auto render = [&](const std::string& name, const std::string& options) {
        const auto result = runTexsplat("render " + scene + " -o " + path(name) +
                                        " --size 32x32 --backend cpu" + options);
        EXPECT_EQ(result.exitCode, 0) << options << ": " << result.standardError;
        return texsplat::image::readImage(path(name));
    };
    const Image perspective = render("perspective.png", "");
    const Image orthographic = render("orthographic.png", " --camera orthographic");
    const Image back = render("back.png", " --camera perspective");
    double sum = 0.0;
    double unchanged = 0.0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const glm::vec4 d = perspective.pixel(x, y) - orthographic.pixel(x, y);
            sum += std::abs(d.r) + std::abs(d.g) + std::abs(d.b);
            const glm::vec4 e = perspective.pixel(x, y) - back.pixel(x, y);
            unchanged += std::abs(e.r) + std::abs(e.g) + std::abs(e.b);
        }
    }
    EXPECT_GT(sum, 0.0) << "a perspective view of a box differs from a parallel one";
    // Measured 0.010: the blob's near and far sides are 20 % nearer and farther than the focal
    // point, so the perspective view shows them 25 % larger and 17 % smaller.
    EXPECT_LT(sum / (32 * 32 * 3), 0.02) << "a narrow angle from afar is almost parallel";
    EXPECT_EQ(unchanged, 0.0) << "--camera of the scene's own kind changes nothing";
}

} // namespace
