// The colour legend drawn into rendered images, and its bitmap number font.

#include "nodes/annotation/ColorLegend.h"
#include "nodes/annotation/LabelFont.h"
#include "nodes/annotation/NumberFont.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawVolume.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::annotation {
namespace {

using nodes::test::errorOf;

nodes::TransferFunction::Ptr magma() {
    auto transfer = nodes::TransferFunction::create();
    transfer->preset.setValue(nodes::ColorPreset::Magma);
    return transfer;
}

ColorLegend legendOf(const nodes::TransferFunction::Ptr& transfer, LegendPosition position) {
    return ColorLegend([transfer](float t) { return transfer->colorAt(t); },
                       glm::vec2(-0.15f, 0.15f), position);
}

TEST(ColorLegend, theBarShowsTheColorMapFromLowToHigh) {
    const auto transfer = magma();
    for (const LegendPosition position : {LegendPosition::Right, LegendPosition::Left,
                                          LegendPosition::Top, LegendPosition::Bottom}) {
        image::Image image(320, 240);
        const ColorLegend legend = legendOf(transfer, position);
        legend.draw(image);
        const image::ImageRegion bar = legend.barRegion(320, 240);
        const bool vertical = position == LegendPosition::Right || position == LegendPosition::Left;
        const int length = vertical ? bar.height : bar.width;
        ASSERT_GT(length, 100);
        for (int i = 0; i < length; ++i) {
            const float t = (float(i) + 0.5f) / float(length);
            const int x = vertical ? bar.x + bar.width / 2 : bar.x + i;
            const int y = vertical ? bar.y + bar.height - 1 - i : bar.y + bar.height / 2;
            EXPECT_EQ(image.pixel(x, y), glm::vec4(transfer->colorAt(t), 1.0f))
                << "position " << int(position) << " pixel " << i;
        }
        // Nothing outside the bar and its labels: the corners stay as they were.
        EXPECT_EQ(image.pixel(0, 0), glm::vec4(0.0f));
        EXPECT_EQ(image.pixel(319, 239), glm::vec4(0.0f));
    }
}

TEST(ColorLegend, labelsAreWrittenBesideTheBar) {
    image::Image image(320, 240);
    const ColorLegend legend = legendOf(magma(), LegendPosition::Right);
    legend.draw(image);
    const image::ImageRegion bar = legend.barRegion(320, 240);
    int white = 0;
    for (int y = 0; y < 240; ++y) {
        for (int x = bar.x + bar.width; x < 320; ++x) {
            white += image.pixel(x, y).r > 0.5f ? 1 : 0; // anti-aliased glyphs
        }
    }
    EXPECT_GT(white, 40);
    // The bar, the gap and the widest label, "-0.15", fit.
    EXPECT_LE(bar.x + bar.width + 3 + LabelFont::forImage(320, 240).textWidth("-0.15"), 320);
}

TEST(ColorLegend, imagesSmallerThanTheLegendGetWhatFits) {
    for (const LegendPosition position : {LegendPosition::Right, LegendPosition::Bottom}) {
        image::Image image(3, 2);
        legendOf(magma(), position).draw(image);
        EXPECT_EQ(image.statistics().nonFinitePixels, 0U);
    }
}

TEST(ColorLegend, labelsAreShortNumbers) {
    EXPECT_EQ(ColorLegend::label(-0.15f), "-0.15");
    EXPECT_EQ(ColorLegend::label(0.0), "0");
    EXPECT_EQ(ColorLegend::label(-0.0), "0");
    EXPECT_EQ(ColorLegend::label(1.0e6), "1e+06");
    EXPECT_EQ(ColorLegend::label(123.456), "123");
}

TEST(ColorLegend, aSceneGivesItsTransferFunctionAndDataRange) {
    nodes::registerNodeTypes();
    volume::DenseScalarGrid grid(volume::GridGeometry({3, 1, 1}));
    grid.setValue({0, 0, 0}, -0.15f);
    grid.setValue({2, 0, 0}, 0.15f);
    const std::string path = nodes::test::testPath("distance.raw");
    volume::writeRawVolume(path, grid);
    auto volume = nodes::VolumeData::create();
    volume->source.setValue(nodes::VolumeSource::FileRaw);
    volume->fileName.setValue(path);
    const auto root = sg::Separator::create();
    root->addChild(magma());
    root->addChild(volume);
    EXPECT_EQ(ColorLegend::ofScene(*root, LegendPosition::Right).range(),
              glm::vec2(-0.15f, 0.15f));
    EXPECT_EQ(errorOf<DataError>([] {
                  ColorLegend::ofScene(*sg::Separator::create(), LegendPosition::Right);
              }),
              "colour legend: the scene has no TransferFunction");
}

TEST(ColorLegend, aSceneGivesWhatItsFirstSplatNodeDraws) {
    // A function and a volume that no splat node draws come first in the file, as a shared
    // mask volume or a function kept for later would: the legend is of what is drawn.
    nodes::registerNodeTypes();
    const auto rawVolume = [](const std::string& name, float low, float high) {
        volume::DenseScalarGrid grid(volume::GridGeometry({3, 1, 1}));
        grid.setValue({0, 0, 0}, low);
        grid.setValue({1, 0, 0}, 0.5f * (low + high));
        grid.setValue({2, 0, 0}, high);
        const std::string path = nodes::test::testPath(name);
        volume::writeRawVolume(path, grid);
        auto volume = nodes::VolumeData::create();
        volume->source.setValue(nodes::VolumeSource::FileRaw);
        volume->fileName.setValue(path);
        return volume;
    };
    auto drawn = nodes::TransferFunction::create();
    drawn->preset.setValue(nodes::ColorPreset::Viridis);
    const auto unused = sg::Separator::create();
    unused->addChild(magma());
    unused->addChild(rawVolume("unused.raw", -0.15f, 0.15f));
    const auto shown = sg::Separator::create();
    shown->addChild(drawn);
    shown->addChild(rawVolume("shown.raw", 2.0f, 10.0f));
    shown->addChild(nodes::TextureSplat::create());
    const auto root = sg::Separator::create();
    root->addChild(unused);
    root->addChild(shown);

    const ColorLegend legend = ColorLegend::ofScene(*root, LegendPosition::Right);
    EXPECT_EQ(legend.range(), glm::vec2(2.0f, 10.0f));
    image::Image image(96, 64);
    legend.draw(image);
    const image::ImageRegion bar = legend.barRegion(96, 64);
    EXPECT_EQ(image.pixel(bar.x + bar.width / 2, bar.y + bar.height - 1),
              glm::vec4(drawn->colorAt(0.5f / static_cast<float>(bar.height)), 1.0f))
        << "the lowest value in the drawn function's colour";
}

TEST(ColorLegend, positionsAreNamed) {
    EXPECT_EQ(parseLegendPosition("bottom"), LegendPosition::Bottom);
    EXPECT_EQ(errorOf<DataError>([] { parseLegendPosition("middle"); }),
              "legend position must be right, left, top or bottom, got 'middle'");
}

TEST(NumberFont, drawsGlyphsAtScale) {
    image::Image image(12, 16);
    NumberFont::draw(image, {0, 0}, "-", 2, glm::vec4(1.0f));
    // '-' is the fourth row of five columns: rows 6 and 7 at scale 2.
    EXPECT_EQ(image.pixel(0, 6), glm::vec4(1.0f));
    EXPECT_EQ(image.pixel(9, 7), glm::vec4(1.0f));
    EXPECT_EQ(image.pixel(0, 5), glm::vec4(0.0f));
    EXPECT_EQ(image.pixel(10, 6), glm::vec4(0.0f));
    EXPECT_EQ(NumberFont::textWidth("-0.15", 1), 29);
    EXPECT_TRUE(NumberFont::hasGlyph('e'));
    EXPECT_FALSE(NumberFont::hasGlyph('x'));
    EXPECT_EQ(errorOf<DataError>([&] { NumberFont::draw(image, {0, 0}, "1x", 1, {}); }),
              "NumberFont: no glyph for 'x'; it writes digits, '-', '+', '.', 'e' and space");
}

TEST(ColorLegend, labelsAreDarkOnALightBackground) {
    // On white the labels are drawn in the other tone than on black: the label area on white is
    // the negative of the label area on black.
    const auto drawnOn = [](float tone) {
        image::Image image(320, 240);
        for (int y = 0; y < 240; ++y)
            for (int x = 0; x < 320; ++x)
                image.setPixel(x, y, glm::vec4(glm::vec3(tone), 1.0f));
        legendOf(magma(), LegendPosition::Right).draw(image);
        return image;
    };
    const image::Image onBlack = drawnOn(0.0f);
    const image::Image onWhite = drawnOn(1.0f);
    const image::ImageRegion bar = legendOf(magma(), LegendPosition::Right).barRegion(320, 240);
    int ink = 0;
    double mismatch = 0.0;
    for (int y = 0; y < 240; ++y)
        for (int x = bar.x + bar.width; x < 320; ++x) {
            ink += onBlack.pixel(x, y).g > 0.5f ? 1 : 0;
            mismatch += std::abs(onWhite.pixel(x, y).g - (1.0f - onBlack.pixel(x, y).g));
        }
    EXPECT_GT(ink, 40);
    EXPECT_LT(mismatch, 1.0);
}

} // namespace
} // namespace texsplat::annotation
