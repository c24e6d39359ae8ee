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

TEST_F(ColorbarCommandTest, theBarShowsTheColorMapInEveryBackend) {
    const std::string scene =
        writeScene("TransferFunction { preset TURBO range 0 1.2 opacities [ 0, 4 ] }\n");
    const auto transfer = nodes::TransferFunction::create();
    transfer->preset.setValue(nodes::ColorPreset::Turbo);
    const annotation::ColorLegend expected([&](float t) { return transfer->colorAt(t); },
                                           glm::vec2(0.0f, 1.2f),
                                           annotation::LegendPosition::Bottom);
    const image::ImageRegion bar = expected.barRegion(160, 120);
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
                // 8-bit sRGB in the PNG: within a step.
                EXPECT_NEAR(pixel[c], color[c], 0.01f) << how << " column " << i;
            }
            EXPECT_EQ(pixel.a, 1.0f) << how;
        }
    }
}

TEST_F(ColorbarCommandTest, badUsesAreNamed) {
    const std::string output = path("legend.png");
    const auto position = runTexsplat("render " + writeScene("TransferFunction { }\n") + " -o " +
                                      output + " --colorbar --colorbar-position middle");
    EXPECT_EQ(position.exitCode, 1);
    EXPECT_EQ(position.standardError,
              "texsplat: error: --colorbar-position: legend position must be right, left, top or "
              "bottom, got 'middle'\n");
}

} // namespace
} // namespace texsplat
