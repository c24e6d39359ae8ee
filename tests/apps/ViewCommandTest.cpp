#include "RunCommand.h"

#include "nodes/image/Image.h"
#include "nodes/image/ImageIo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using texsplat::test::runTexsplat;

namespace {

// The viewer needs a display: the tests give it a virtual one with Debian's xvfb-run.
bool hasXvfbRun() { return std::system("command -v xvfb-run > /dev/null 2>&1") == 0; }

const std::string kNoDisplay = "env -u DISPLAY -u WAYLAND_DISPLAY";

class ViewCommandTest : public texsplat::test::ScratchDirectoryTest {
protected:
    void SetUp() override {
#ifndef TEXSPLAT_WITH_VIEWER
        GTEST_SKIP() << "built without the viewer (TEXSPLAT_WITH_VIEWER=OFF)";
#endif
        ScratchDirectoryTest::SetUp();
    }
};

// One test starts Xvfb (parallel xvfb-run calls may race for a display number).
TEST_F(ViewCommandTest, showsTheDefaultSceneInAWindowAndWritesItsLastFrame) {
    if (!hasXvfbRun()) {
        GTEST_SKIP() << "xvfb-run is not installed (Debian package xvfb)";
    }
    const std::string screenshot = path("view.png");
    const auto output =
        runTexsplat("view --frames 3 --size 96x80 --screenshot " + screenshot, "xvfb-run -a");
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    const texsplat::image::Image image = texsplat::image::readImage(screenshot);
    ASSERT_EQ(image.width(), 96);
    ASSERT_EQ(image.height(), 80);
    // The tornado fills the middle of the view, far brighter than the dark background at the
    // corner; the background is opaque, so the PNG is too.
    const glm::vec4 corner = image.pixel(0, 0);
    const glm::vec4 centre = image.pixel(48, 40);
    EXPECT_LT(corner.r, 0.05f);
    EXPECT_GT(centre.r, corner.r + 0.2f);
    EXPECT_FLOAT_EQ(centre.a, 1.0f);

    // The window shows what `render` draws (same framing, upright), over the viewer's dark
    // background (0.02) instead of black.
    const std::string rendered = path("render.png");
    const auto renderOutput = runTexsplat("render --size 96x80 -o " + rendered);
    ASSERT_EQ(renderOutput.exitCode, 0) << renderOutput.standardError;
    const texsplat::image::Image reference = texsplat::image::readImage(rendered);
    float largest = 0.0f;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const glm::vec4 difference = image.pixel(x, y) - reference.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                largest = std::max(largest, std::abs(difference[c]));
            }
        }
    }
    EXPECT_LT(largest, 0.035f);
}

TEST_F(ViewCommandTest, showsTheSameFramesWithEitherBackend) {
    if (!hasXvfbRun()) {
        GTEST_SKIP() << "xvfb-run is not installed (Debian package xvfb)";
    }
    std::vector<texsplat::image::Image> images;
    for (const char* backend : {"cpu", "gl"}) {
        const std::string screenshot = path(std::string("view-") + backend + ".png");
        const auto output = runTexsplat("view --frames 2 --size 64x48 --backend " +
                                            std::string(backend) + " --screenshot " + screenshot,
                                        "xvfb-run -a");
        ASSERT_EQ(output.exitCode, 0) << backend << ": " << output.standardError;
        images.push_back(texsplat::image::readImage(screenshot));
    }
    float largest = 0.0f;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            const glm::vec4 difference = images[0].pixel(x, y) - images[1].pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                largest = std::max(largest, std::abs(difference[c]));
            }
        }
    }
    EXPECT_GT(images[0].pixel(32, 24).r, 0.1f) << "the tornado in the middle";
    // The backends differ by up to 0.016 in the tornado's brightest splats (the CPU backend's
    // stamps, docs/backends.md): 4 steps of the 8-bit colour values.
    EXPECT_LE(largest, 4.0f / 255.0f) << "the PNGs' 8 bits, but for the backends' rounding";
}

TEST_F(ViewCommandTest, startsCoarseRefinesToFullQualityAndReportsEachFrame) {
    if (!hasXvfbRun()) {
        GTEST_SKIP() << "xvfb-run is not installed (Debian package xvfb)";
    }
    // The tornado's 92,299 voxels: 1000 splats first, then 4000, 16000, 64000, 256000 (which
    // holds them all: the full-resolution list, which is what the scene's own settings draw, so
    // no frame follows). A step slower than ProgressiveRefinement::kQuickStepSeconds (the 64000
    // one under a sanitizer) is followed by the full-quality frame instead.
    const auto output = runTexsplat(
        "view --frames 14 --size 64x48 --interactive-splats 1000 --time-report", "xvfb-run -a");
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    std::istringstream lines(output.standardError);
    std::vector<std::string> frames;
    for (std::string line; std::getline(lines, line);) {
        frames.push_back(line);
    }
    ASSERT_GE(frames.size(), 3u) << output.standardError;
    EXPECT_EQ(frames.front().rfind("frame 0 at ", 0), 0u) << frames.front();
    EXPECT_NE(frames.front().find(": interactive (coarse octree cut), budget 1000, "),
              std::string::npos)
        << frames.front();
    EXPECT_NE(frames[1].find(": refining while idle, budget 4000, "), std::string::npos)
        << frames[1];
    const std::string& last = frames.back();
    if (last.rfind("at ", 0) == 0) {
        // The last step drew every voxel: it is the full-quality frame, not drawn again.
        EXPECT_NE(last.find(": full quality, the last frame's 92299 splats"), std::string::npos)
            << output.standardError;
        const std::string& step = frames[frames.size() - 2];
        EXPECT_NE(step.find(": refining while idle, budget 256000, 92299 splats; "),
                  std::string::npos)
            << output.standardError;
        EXPECT_NE(step.find(" draw "), std::string::npos) << step;
    } else {
        EXPECT_NE(last.find(": full quality, 92299 splats; "), std::string::npos)
            << output.standardError;
        EXPECT_NE(last.find(" draw "), std::string::npos) << last;
    }
}

TEST_F(ViewCommandTest, aKeyTappedWhileAFrameRendersIsNotLost) {
    // The viewer reads keys by polling between frames and during long steps. A tap of Esc while
    // it is busy arrives with its release in one poll; without sticky keys it read as released
    // and the viewer went on (a tap during a long frame of a big volume was lost). The viewer is
    // stopped (SIGSTOP) while the key goes down and up, so the two arrive together every time.
    if (!hasXvfbRun() || std::system("command -v xdotool > /dev/null 2>&1") != 0) {
        GTEST_SKIP() << "needs xvfb-run and xdotool (Debian packages xvfb, xdotool)";
    }
    const std::string script = write("tap.sh", std::string(R"(
"$1" view --size 96x80 --frames 0 2> "$2" &
viewer=$!
window=$(timeout 60 xdotool search --sync --name texsplat | head -n 1)
[ -n "$window" ] || { kill $viewer; echo "no window"; exit 3; }
kill -STOP $viewer
xdotool key --window "$window" Escape
kill -CONT $viewer
for step in $(seq 600); do kill -0 $viewer 2> /dev/null || break; sleep 0.1; done
if kill -0 $viewer 2> /dev/null; then kill $viewer; echo "still running a minute after Esc"; exit 4; fi
wait $viewer
)"));
    const std::string errors = path("viewer-stderr.txt");
    const std::string command = "xvfb-run -a sh " + script + " " TEXSPLAT_EXECUTABLE " " +
                                errors + " > " + path("tap-stdout.txt") + " 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_EQ(status, 0) << read(path("tap-stdout.txt")) << read(errors);
}

TEST_F(ViewCommandTest, withoutADisplayItSaysSoAndWritesNothing) {
    const std::string screenshot = path("view.png");
    const auto output =
        runTexsplat("view --frames 1 --screenshot " + screenshot, kNoDisplay);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError,
              "texsplat: error: cannot open a window: X11: The DISPLAY environment variable is "
              "missing; no display (DISPLAY and WAYLAND_DISPLAY are unset); 'texsplat render' "
              "makes images without a display\n");
    EXPECT_FALSE(fs::exists(screenshot));
}

TEST_F(ViewCommandTest, badInputsAreReportedBeforeAWindowOpens) {
    const std::string missing = path("missing.iv");
    auto output = runTexsplat("view " + missing, kNoDisplay);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError.rfind("texsplat: error: " + missing + ": ", 0), 0u)
        << output.standardError;
    output = runTexsplat("view --size 0x10", kNoDisplay);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError,
              "texsplat: error: --size: expected WxH with whole numbers from 1 to 16384, got "
              "'0x10'\n");
    output = runTexsplat("view --screenshot " + path("view.tiff"), kNoDisplay);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_NE(output.standardError.find("view.tiff"), std::string::npos) << output.standardError;
}

} // namespace
