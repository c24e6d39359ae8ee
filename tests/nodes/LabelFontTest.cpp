// The label font of annotations: DejaVu Sans through stb_truetype, or the number font when the
// font file cannot be read.

#include "nodes/annotation/LabelFont.h"

#include "SceneNodesTestSupport.h"
#include "nodes/annotation/NumberFont.h"
#include "scenegraph/Log.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace texsplat::annotation {
namespace {

// The warnings logged while `body` runs.
template <class F> std::vector<std::string> warningsOf(F&& body) {
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning) {
            warnings.emplace_back(message);
        }
    });
    body();
    setLogSink(previous);
    return warnings;
}

TEST(LabelFont, drawsAntiAliasedGlyphsOfTheBuildsFont) {
    if (LabelFont::kDefaultFile.empty()) {
        GTEST_SKIP() << "no DejaVuSans.ttf was found at build time (Debian: fonts-dejavu-core)";
    }
    const LabelFont font(LabelFont::kDefaultFile, 24, 1);
    ASSERT_TRUE(font.isTrueType());
    EXPECT_GE(font.height(), 24);
    EXPECT_LE(font.height(), 26);
    EXPECT_GT(font.textWidth("-0.15"), font.textWidth("0.1"));
    image::Image image(80, 32);
    font.draw(image, {2, 2}, "0.5", glm::vec4(1.0f));
    int full = 0;
    int partial = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const float red = image.pixel(x, y).r;
            full += red == 1.0f ? 1 : 0;
            partial += red > 0.05f && red < 0.95f ? 1 : 0;
        }
    }
    EXPECT_GT(full, 20);    // the strokes' inside
    EXPECT_GT(partial, 20); // their anti-aliased edges
    // Nothing right of the text's width.
    EXPECT_EQ(image.pixel(2 + font.textWidth("0.5") + 1, 14), glm::vec4(0.0f));
}

TEST(LabelFont, turnsTextToReadFromBottomToTop) {
    for (const std::string& file :
         std::vector<std::string>{LabelFont::kDefaultFile, nodes::test::testPath("none.ttf")}) {
        const LabelFont font(file, 16, 2);
        const int width = font.textWidth("1.5");
        const int height = font.height();
        image::Image upright(width + 4, height + 4);
        font.draw(upright, {2, 2}, "1.5", glm::vec4(1.0f));
        image::Image turned(height + 4, width + 4);
        font.draw(turned, {2, 2}, "1.5", glm::vec4(1.0f), TextDirection::BottomToTop);
        // The upright text's pixel (x, y) is the turned text's (y, width - 1 - x).
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                ASSERT_EQ(turned.pixel(2 + y, 2 + width - 1 - x), upright.pixel(2 + x, 2 + y))
                    << file << " at " << x << ", " << y;
            }
    }
}

TEST(LabelFont, drawsUtf8Text) {
    if (LabelFont::kDefaultFile.empty()) {
        GTEST_SKIP() << "no DejaVuSans.ttf was found at build time (Debian: fonts-dejavu-core)";
    }
    const LabelFont font(LabelFont::kDefaultFile, 24, 1);
    EXPECT_TRUE(font.canDraw("Temperature (°C)"));
    // "°" is one glyph, not two Latin-1 ones ("Â°"); a lone byte that starts no UTF-8 character
    // is the Latin-1 character of its value.
    EXPECT_EQ(font.textWidth("\xc2\xb0"), font.textWidth("\xb0"));
    EXPECT_LT(font.textWidth("\xc2\xb0"), font.textWidth("\xc2") + font.textWidth("\xb0"));
    EXPECT_FALSE(LabelFont(nodes::test::testPath("none.ttf"), 24, 1).canDraw("K"));
    EXPECT_TRUE(LabelFont(nodes::test::testPath("none.ttf"), 24, 1).canDraw("-1.5e+06"));
}

TEST(LabelFont, growsWithTheImage) {
    if (LabelFont::kDefaultFile.empty()) {
        GTEST_SKIP() << "no DejaVuSans.ttf was found at build time (Debian: fonts-dejavu-core)";
    }
    EXPECT_EQ(LabelFont::forImage(320, 240).height(), LabelFont::forImage(100, 100).height());
    EXPECT_GT(LabelFont::forImage(1024, 1024).height(),
              2 * LabelFont::forImage(320, 240).height() - 2);
}

TEST(LabelFont, fallsBackToTheNumberFontWithOneWarningPerFile) {
    const std::string missing = nodes::test::testPath("missing.ttf");
    const std::vector<std::string> warnings = warningsOf([&] {
        const LabelFont font(missing, 24, 2);
        EXPECT_FALSE(font.isTrueType());
        EXPECT_EQ(font.textWidth("-0.15"), NumberFont::textWidth("-0.15", 2));
        EXPECT_EQ(font.height(), 2 * NumberFont::kGlyphHeight);
        image::Image image(40, 20);
        font.draw(image, {0, 0}, "-", glm::vec4(1.0f));
        EXPECT_EQ(image.pixel(0, 6), glm::vec4(1.0f)); // '-' is NumberFont's fourth row
        EXPECT_FALSE(LabelFont(missing, 12, 1).isTrueType());
    });
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "labels use the built-in bitmap font: " + missing +
                               ": cannot open: No such file or directory");
}

TEST(LabelFont, aFileThatIsNoFontIsNamed) {
    const std::string path = nodes::test::testPath("notes.ttf");
    std::ofstream(path) << "not a font\n";
    const std::vector<std::string> warnings =
        warningsOf([&] { EXPECT_FALSE(LabelFont(path, 24, 1).isTrueType()); });
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "labels use the built-in bitmap font: " + path + ": not a TrueType font");
}

} // namespace
} // namespace texsplat::annotation
