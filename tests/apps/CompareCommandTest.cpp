#include "RunCommand.h"

#include "nodes/image/ImageIo.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <unistd.h>

namespace fs = std::filesystem;
using texsplat::image::Image;
using texsplat::test::runTexsplat;

namespace {

/// Writes a reference and test image pair into a fresh directory: the test image's R channel is
/// 1/8 above the reference everywhere, and one pixel of it differs by 0.5 in B.
class CompareCommandTest : public texsplat::test::ScratchDirectoryTest {
protected:
    void SetUp() override {
        if (!texsplat::image::isExrSupported())
            GTEST_SKIP() << "built without OpenEXR";
        ScratchDirectoryTest::SetUp();
        Image reference(8, 4);
        Image test(8, 4);
        reference.fill({0.25f, 0.5f, 0.5f, 1.0f});
        test.fill({0.375f, 0.5f, 0.5f, 1.0f});
        test.setPixel(5, 2, {0.375f, 0.5f, 1.0f, 1.0f});
        texsplat::image::writeImage(reference, path("reference.exr"));
        texsplat::image::writeImage(test, path("test.exr"));
        test.setPixel(0, 0, glm::vec4(std::numeric_limits<float>::quiet_NaN()));
        texsplat::image::writeImage(test, path("nan.exr"));
        texsplat::image::writeImage(Image(8, 3), path("small.exr"));
    }
};

} // namespace

TEST_F(CompareCommandTest, printsErrorsPerChannelAndOverRgb) {
    const auto output = runTexsplat("compare " + path("reference.exr") + " " + path("test.exr"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    const std::string& text = output.standardOutput;
    EXPECT_NE(text.find("compared   32 pixels in region 0,0 8x4; 0 non-finite left out"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("R        1.250000e-01     18.062  1.250000e-01   (0, 0)"),
              std::string::npos)
        << text;
    // B: one pixel off by 0.5 → RMSE √(0.25 / 32) = 0.0883883.
    EXPECT_NE(text.find("B        8.838835e-02     21.072  5.000000e-01   (5, 2)"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("A        0.000000e+00        inf  0.000000e+00   (0, 0)"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("RGB      8.838835e-02     21.072  5.000000e-01   (5, 2) in B"),
              std::string::npos)
        << text;
    EXPECT_TRUE(output.standardError.empty()) << output.standardError;
}

TEST_F(CompareCommandTest, jsonHasTheSameNumbers) {
    const auto output =
        runTexsplat("compare --json " + path("reference.exr") + " " + path("test.exr"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    const std::string& json = output.standardOutput;
    EXPECT_NE(json.find("\"comparedPixels\": 32,"), std::string::npos) << json;
    EXPECT_NE(json.find("\"nonFinitePixels\": 0,"), std::string::npos) << json;
    EXPECT_NE(json.find("\"R\": {\"rmse\": 0.125, \"psnr\": 18.0617997, \"maxAbsError\": 0.125, "
                        "\"maxAt\": [0, 0]}"),
              std::string::npos)
        << json;
    EXPECT_NE(json.find("\"A\": {\"rmse\": 0, \"psnr\": null,"), std::string::npos) << json;
    EXPECT_NE(json.find("\"maxChannel\": \"B\""), std::string::npos) << json;
    EXPECT_EQ(json.front(), '{');
    EXPECT_EQ(json.substr(json.size() - 2), "}\n");
}

TEST_F(CompareCommandTest, diffOptionWritesTheFalseColorImage) {
    const std::string diff = path("diff.png");
    const auto output = runTexsplat("compare " + path("reference.exr") + " " + path("test.exr") +
                                    " --diff " + diff);
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    ASSERT_TRUE(fs::exists(diff));
    const Image image = texsplat::image::readImage(diff);
    EXPECT_EQ(image.width(), 8);
    EXPECT_EQ(image.height(), 4);
    EXPECT_EQ(image.pixel(0, 0).a, 1.0f);
    // The largest error (5, 2) is at the yellow end of viridis, (253, 231, 37) in the file, the
    // others well below it, in its blues.
    EXPECT_NEAR(image.pixel(5, 2).r, 253.0f / 255.0f, 0.5f / 255.0f);
    EXPECT_NEAR(image.pixel(5, 2).b, 37.0f / 255.0f, 0.5f / 255.0f);
    EXPECT_LT(image.pixel(0, 0).r, 0.3f);
    EXPECT_NE(output.standardOutput.find("diff       " + diff + " (viridis from 0 to 0.2"),
              std::string::npos)
        << output.standardOutput;
}

TEST_F(CompareCommandTest, regionLimitsTheComparison) {
    const auto output = runTexsplat("compare --region 0,0,4,2 " + path("reference.exr") + " " +
                                    path("test.exr") + " --json");
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("\"comparedPixels\": 8,"), std::string::npos);
    EXPECT_NE(output.standardOutput.find("\"B\": {\"rmse\": 0, \"psnr\": null"),
              std::string::npos)
        << output.standardOutput;
}

TEST_F(CompareCommandTest, nonFinitePixelsAreReported) {
    const auto output = runTexsplat("compare " + path("reference.exr") + " " + path("nan.exr"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find("31 pixels in region 0,0 8x4; 1 non-finite left out"),
              std::string::npos)
        << output.standardOutput;
    EXPECT_EQ(output.standardError,
              "texsplat: warning: " + path("nan.exr") +
                  ": left out 1 pixel(s) with NaN or infinite values in one of the images\n");
}

TEST_F(CompareCommandTest, sizeMismatchExitsWithOne) {
    const auto output = runTexsplat("compare " + path("reference.exr") + " " + path("small.exr"));
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: " + path("small.exr") +
                                        ": image sizes differ: reference 8x4, test 8x3\n");
    EXPECT_TRUE(output.standardOutput.empty());
}

TEST_F(CompareCommandTest, missingFileExitsWithOne) {
    const auto output = runTexsplat("compare " + path("none.exr") + " " + path("test.exr"));
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: " + path("none.exr") +
                                        ": cannot open: No such file or directory\n");
}

TEST_F(CompareCommandTest, unwritableDiffExitsWithOneAndWritesNothing) {
    const std::string diff = path("missing/diff.png");
    const auto output = runTexsplat("compare " + path("reference.exr") + " " + path("test.exr") +
                                    " --diff " + diff);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: " + diff +
                                        ": cannot write the difference image: folder '" +
                                        path("missing") + "' does not exist\n");
    EXPECT_FALSE(fs::exists(path("missing")));
}

TEST_F(CompareCommandTest, badRegionIsAnError) {
    const auto outside = runTexsplat("compare --region 6,0,4,4 " + path("reference.exr") + " " +
                                     path("test.exr"));
    EXPECT_EQ(outside.exitCode, 1);
    EXPECT_EQ(outside.standardError, "texsplat: error: " + path("test.exr") +
                                         ": region 6,0 4x4 is not inside the 8x4 image\n");
    const auto shortRegion =
        runTexsplat("compare --region 1,2,3 " + path("reference.exr") + " " + path("test.exr"));
    EXPECT_NE(shortRegion.exitCode, 0);
    EXPECT_NE(shortRegion.standardError.find(
                  "--region: '1,2,3' is not X,Y,WIDTH,HEIGHT (four integers)"),
              std::string::npos)
        << shortRegion.standardError;
}

TEST_F(CompareCommandTest, imagesTooLargeForTheMemoryLimitAreRefusedFromTheirHeaders) {
    // A 1000 x 1000 PNG of one colour is a few kilobytes; decoding it takes 24 bytes a pixel.
    Image large(1000, 1000);
    large.fill({0.5f, 0.5f, 0.5f, 1.0f});
    const std::string png = path("large.png");
    texsplat::image::writeImage(large, png);
    const auto result = runTexsplat("compare " + png + " " + png + " --memory-limit 10M");
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_EQ(result.standardError,
              "texsplat: error: " + png + ": decoding its 1000 x 1000 pixels would need 24000000 "
              "bytes (22.9 MiB), more than the memory limit of 10485760 bytes (10 MiB); use "
              "smaller images, or a larger --memory-limit\n");
    EXPECT_EQ(runTexsplat("compare " + png + " " + png + " --memory-limit 64M").exitCode, 0);
}
