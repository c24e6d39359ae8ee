// `texsplat render --colorbar`: the legend drawn into the image by either backend and the
// reference, its bar's pixels the transfer function's colours.

#include "RunCommand.h"

#include "nodes/TransferFunction.h"
#include "nodes/annotation/ColorLegend.h"
#include "nodes/image/ImageIo.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace texsplat {
namespace {

using test::runTexsplat;

class ColorbarCommandTest : public test::ScratchDirectoryTest {
protected:
    std::string writeScene(const std::string& transfer) const {
        const std::string scene = path("blob.iv");
        std::ofstream(scene) << "#Inventor V2.1 ascii\nSeparator {\n" << transfer
                             << "VolumeData { source BLOB resolution 12 12 12 }\n"
                                "TextureSplat { }\n}\n";
        return scene;
    }
};

TEST_F(ColorbarCommandTest, theBarsStandBesideThePictureItsSizeAsAskedFor) {
    const std::string scene =
        writeScene("TransferFunction { preset TURBO range 0 1.2 opacities [ 0, 4 ] }\n");
    const std::string picture = path("picture.png");
    const std::string figure = path("figure.png");
    ASSERT_EQ(runTexsplat("render " + scene + " -o " + picture + " --size 160x120 --backend cpu")
                  .exitCode,
              0);
    ASSERT_EQ(runTexsplat("render " + scene + " -o " + figure +
                          " --size 160x120 --backend cpu --colorbar")
                  .exitCode,
              0);
    const image::Image alone = image::readImage(picture);
    const image::Image beside = image::readImage(figure);
    EXPECT_EQ(beside.height(), 120);
    EXPECT_GT(beside.width(), 160);
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            ASSERT_EQ(beside.pixel(x, y), alone.pixel(x, y)) << "at " << x << ", " << y;
        }
}

TEST_F(ColorbarCommandTest, theBarShowsTheColorMapInEveryBackend) {
    const std::string scene =
        writeScene("TransferFunction { preset TURBO range 0 1.2 opacities [ 0, 4 ] }\n");
    const auto transfer = nodes::TransferFunction::create();
    transfer->preset.setValue(nodes::ColorPreset::Turbo);
    const annotation::ColorLegend expected(
        {{[&](float t) { return transfer->colorAt(t); }, glm::vec2(0.0f, 1.2f), ""}},
        {annotation::LegendPosition::Bottom, 5}, 160, 120);
    const image::ImageRegion bar = expected.barRegion(0);
    for (const std::string how : {"--backend cpu", "--backend gl", "--raycast"}) {
        const std::string output = path("legend.png");
        const auto result = runTexsplat("render " + scene + " -o " + output +
                                        " --size 160x120 --colorbar --colorbar-position bottom " +
                                        how);
        ASSERT_EQ(result.exitCode, 0) << how << ": " << result.standardError;
        const image::Image image = image::readImage(output);
        for (int i = 0; i < bar.width; ++i) {
            const float t = (float(i) + 0.5f) / float(bar.width);
            const glm::vec4 pixel = image.pixel(bar.x + i, bar.y + bar.height / 2);
            const glm::vec3 color = transfer->colorAt(t);
            for (int c = 0; c < 3; ++c) {
                // The colour map's values as they are, in 8 bits: within half a step.
                EXPECT_NEAR(pixel[c], color[c], 0.5f / 255.0f + 1e-6f) << how << " column " << i;
            }
            EXPECT_EQ(pixel.a, 1.0f) << how;
        }
    }
}

TEST_F(ColorbarCommandTest, theTitleComesFromTheTransferFunctionOrTheCommandLine) {
    const std::string scene = writeScene(
        "TransferFunction { preset TURBO range 0 1.2 title \"Density\" units \"g/cm³\" }\n");
    const auto render = [&](const std::string& options) {
        const std::string output = path("legend.png");
        const auto result = runTexsplat("render " + scene + " -o " + output +
                                        " --size 160x120 --backend cpu --colorbar " + options);
        EXPECT_EQ(result.exitCode, 0) << options << ": " << result.standardError;
        return image::readImage(output);
    };
    const image::Image fromScene = render("");
    const image::Image untitled = render("--colorbar-title ''");
    const image::Image retitled = render("--colorbar-title 'Cloud water'");
    EXPECT_GT(fromScene.width(), untitled.width()) << "the scene's title takes room beside the bar";
    ASSERT_EQ(retitled.width(), fromScene.width())
        << "a title runs along the bar, whatever its length";
    int differing = 0;
    for (int y = 0; y < fromScene.height(); ++y)
        for (int x = 0; x < fromScene.width(); ++x) {
            differing += retitled.pixel(x, y) != fromScene.pixel(x, y) ? 1 : 0;
        }
    EXPECT_GT(differing, 30) << "the option's title replaces the scene's";
    EXPECT_EQ(runTexsplat("render " + scene + " -o " + path("two.png") +
                          " --colorbar --colorbar-title A --colorbar-title B")
                  .standardError,
              "texsplat: error: --colorbar-title: given 2 times, but the scene has 1 colour bar\n");
}

TEST_F(ColorbarCommandTest, badUsesAreNamed) {
    const std::string output = path("legend.png");
    const auto position = runTexsplat("render " + writeScene("TransferFunction { }\n") + " -o " +
                                      output + " --colorbar --colorbar-position middle");
    EXPECT_EQ(position.exitCode, 1);
    EXPECT_EQ(position.standardError,
              "texsplat: error: --colorbar-position: legend position must be right, left, top or "
              "bottom, got 'middle'\n");
    const auto title = runTexsplat("render " + writeScene("TransferFunction { }\n") + " -o " +
                                   output + " --colorbar-title Density");
    EXPECT_EQ(title.exitCode, 2); // a usage error, CLI11's
    const std::string expected = "texsplat: error: --colorbar-title requires --colorbar\n";
    EXPECT_EQ(title.standardError.substr(0, expected.size()), expected);
}

} // namespace
} // namespace texsplat
