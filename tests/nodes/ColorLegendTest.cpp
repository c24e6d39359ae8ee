// The colour bars of a figure: beside the picture, round ticks, titles, ink that reads on the
// background, one bar per colour scale of the scene; and the bitmap number font.

#include "nodes/annotation/ColorLegend.h"
#include "nodes/annotation/LabelFont.h"
#include "nodes/annotation/NumberFont.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VectorSplat.h"
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

ColorBar barOf(const nodes::TransferFunction::Ptr& transfer, glm::vec2 range = {-0.15f, 0.15f},
               std::string title = {}) {
    return {[transfer](float t) { return transfer->colorAt(t); }, range, std::move(title)};
}

ColorLegend legendOf(const nodes::TransferFunction::Ptr& transfer, LegendPosition position,
                     int width = 320, int height = 240) {
    return ColorLegend({barOf(transfer)}, {position, 5}, width, height);
}

bool hasTrueTypeFont() { return !LabelFont::kDefaultFile.empty(); }

// Whether `a` and `b` overlap.
bool overlap(const image::ImageRegion& a, const image::ImageRegion& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

// A picture of one colour, of the legend's data region.
image::Image pictureFor(const ColorLegend& legend, const glm::vec4& color) {
    image::Image picture(legend.dataRegion().width, legend.dataRegion().height);
    picture.fill(color);
    return picture;
}

TEST(ColorLegend, theBarShowsTheColorMapFromLowToHigh) {
    const auto transfer = magma();
    for (const LegendPosition position : {LegendPosition::Right, LegendPosition::Left,
                                          LegendPosition::Top, LegendPosition::Bottom}) {
        const ColorLegend legend = legendOf(transfer, position);
        const image::Image figure =
            legend.compose(pictureFor(legend, glm::vec4(0, 0, 0, 1)), glm::vec4(0, 0, 0, 1));
        const image::ImageRegion bar = legend.barRegion(0);
        const bool vertical = position == LegendPosition::Right || position == LegendPosition::Left;
        const int length = vertical ? bar.height : bar.width;
        ASSERT_GT(length, 100);
        for (int i = 0; i < length; ++i) {
            const float t = (float(i) + 0.5f) / float(length);
            const int x = vertical ? bar.x + bar.width / 2 : bar.x + i;
            const int y = vertical ? bar.y + bar.height - 1 - i : bar.y + bar.height / 2;
            EXPECT_EQ(figure.pixel(x, y), glm::vec4(transfer->colorAt(t), 1.0f))
                << "position " << int(position) << " pixel " << i;
        }
    }
}

TEST(ColorLegend, theBarsStandBesideThePictureNeverOverIt) {
    const auto transfer = magma();
    const glm::vec4 red(1.0f, 0.0f, 0.0f, 1.0f);
    for (const LegendPosition position : {LegendPosition::Right, LegendPosition::Left,
                                          LegendPosition::Top, LegendPosition::Bottom}) {
        const ColorLegend legend({barOf(transfer, {0, 1}, "Density"), barOf(transfer, {2, 8})},
                                 {position, 5}, 320, 240);
        const image::ImageRegion data = legend.dataRegion();
        // The picture keeps its size; the figure grows by the strip on the bars' side.
        EXPECT_EQ(data.width, 320);
        EXPECT_EQ(data.height, 240);
        const bool vertical = position == LegendPosition::Right || position == LegendPosition::Left;
        const glm::ivec2 size = legend.figureSize();
        EXPECT_EQ(vertical ? size.y : size.x, vertical ? 240 : 320);
        EXPECT_GT(vertical ? size.x : size.y, vertical ? 320 : 240) << int(position);
        EXPECT_EQ(data.x == 0 && data.y == 0,
                  position == LegendPosition::Right || position == LegendPosition::Bottom);
        EXPECT_FALSE(overlap(data, legend.barRegion(0)));
        EXPECT_FALSE(overlap(data, legend.barRegion(1)));
        EXPECT_FALSE(overlap(legend.barRegion(0), legend.barRegion(1)));
        const image::Image figure = legend.compose(pictureFor(legend, red), glm::vec4(1.0f));
        ASSERT_EQ(figure.width(), size.x);
        ASSERT_EQ(figure.height(), size.y);
        for (int y = data.y; y < data.y + data.height; ++y)
            for (int x = data.x; x < data.x + data.width; ++x) {
                ASSERT_EQ(figure.pixel(x, y), red) << "position " << int(position) << " at " << x
                                                   << ", " << y << ": the picture is untouched";
            }
    }
}

TEST(ColorLegend, aPictureWithDepthKeepsItAndTheStripHasNoSurface) {
    const ColorLegend legend = legendOf(magma(), LegendPosition::Right);
    image::Image picture = pictureFor(legend, glm::vec4(0.5f));
    picture.addDepth(0.25f);
    const image::Image figure = legend.compose(picture, glm::vec4(0.0f));
    ASSERT_TRUE(figure.hasDepth());
    EXPECT_EQ(figure.depth(0, 0), 0.25f);
    EXPECT_EQ(figure.depth(figure.width() - 1, 0), 1.0f);
}

TEST(ColorLegend, ticksAreRoundValuesInsideTheRange) {
    // The range: not -0.00743 / 0.609 / 1.22 but round values.
    EXPECT_EQ(ColorLegend::ticks({-0.00743f, 1.22f}, 3), (std::vector<double>{0.0, 0.5, 1.0}));
    const std::vector<double> five = ColorLegend::ticks({-0.00743f, 1.22f}, 5);
    EXPECT_EQ(five, (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
    EXPECT_EQ(ColorLegend::ticks({0.0f, 1.2f}, 7),
              (std::vector<double>{0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2}));
    EXPECT_EQ(ColorLegend::ticks({-0.15f, 0.15f}, 3), (std::vector<double>{-0.1, 0.0, 0.1}));
    EXPECT_EQ(ColorLegend::ticks({250.0f, 1750.0f}, 4),
              (std::vector<double>{500.0, 1000.0, 1500.0}));
    const std::vector<double> many = ColorLegend::ticks({0.0f, 1.0f}, 20);
    EXPECT_GE(many.size(), 11u);
    EXPECT_LE(many.size(), 21u);
    EXPECT_EQ(ColorLegend::ticks({3.0f, 3.0f}, 5), std::vector<double>{3.0});
}

TEST(ColorLegend, tickLabelsHaveTheDecimalsTheirStepNeeds) {
    EXPECT_EQ(ColorLegend::tickLabels({0.0, 0.25, 0.5, 0.75, 1.0}),
              (std::vector<std::string>{"0.00", "0.25", "0.50", "0.75", "1.00"}));
    EXPECT_EQ(ColorLegend::tickLabels({-0.1, 0.0, 0.1}),
              (std::vector<std::string>{"-0.1", "0.0", "0.1"}));
    EXPECT_EQ(ColorLegend::tickLabels({500.0, 1000.0, 1500.0}),
              (std::vector<std::string>{"500", "1000", "1500"}));
    EXPECT_EQ(ColorLegend::tickLabels({0.0, 2e6, 4e6}),
              (std::vector<std::string>{"0e+00", "2e+06", "4e+06"}));
    EXPECT_EQ(ColorLegend::tickLabels({2.5e-5, 5e-5}),
              (std::vector<std::string>{"2.5e-05", "5.0e-05"}));
    EXPECT_EQ(ColorLegend::tickLabels({3.0}), std::vector<std::string>{"3"});
}

TEST(ColorLegend, inkReadsOnTheBackground) {
    const glm::vec4 black(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_EQ(ColorLegend::inkFor(glm::vec4(1.0f)), black);
    EXPECT_EQ(ColorLegend::inkFor(glm::vec4(0.0f)), black) << "transparent: a page of its own";
    EXPECT_EQ(ColorLegend::inkFor(black), glm::vec4(1.0f));
    EXPECT_EQ(ColorLegend::inkFor(glm::vec4(0.9f, 0.9f, 0.6f, 1.0f)), black);
}

TEST(ColorLegend, labelsAreInkOnTheBackgroundBesideTheBar) {
    for (const glm::vec4& background : {glm::vec4(1.0f), glm::vec4(0, 0, 0, 1), glm::vec4(0.0f)}) {
        const ColorLegend legend = legendOf(magma(), LegendPosition::Right);
        const image::Image figure =
            legend.compose(pictureFor(legend, glm::vec4(0.3f, 0.3f, 0.3f, 1.0f)), background);
        const image::ImageRegion bar = legend.barRegion(0);
        const glm::vec4 ink = ColorLegend::inkFor(background);
        int inked = 0;
        int other = 0;
        for (int y = 0; y < figure.height(); ++y)
            for (int x = bar.x + bar.width + 2; x < figure.width(); ++x) {
                // Anything but ink, background and their anti-aliased mixtures is not text.
                const glm::vec4 away = figure.pixel(x, y) - background;
                const glm::vec4 along = ink - background;
                const float s = glm::dot(away, along) / glm::dot(along, along);
                inked += s > 0.5f ? 1 : 0;
                other += glm::length(away - s * along) > 0.02f ? 1 : 0;
            }
        EXPECT_GT(inked, 40) << "background " << background.r << " " << background.a;
        EXPECT_EQ(other, 0) << "background " << background.r << " " << background.a;
    }
}

TEST(ColorLegend, aTitleIsDrawnAlongTheBar) {
    if (!hasTrueTypeFont()) {
        GTEST_SKIP() << "no DejaVuSans.ttf was found at build time (Debian: fonts-dejavu-core)";
    }
    const auto transfer = magma();
    for (const LegendPosition position : {LegendPosition::Right, LegendPosition::Bottom}) {
        const ColorLegend untitled({barOf(transfer)}, {position, 5}, 320, 240);
        const ColorLegend titled({barOf(transfer, {-0.15f, 0.15f}, "Distance (µm)")},
                                 {position, 5}, 320, 240);
        // The title takes room of its own.
        const bool vertical = position == LegendPosition::Right;
        EXPECT_GT(vertical ? titled.figureSize().x : titled.figureSize().y,
                  vertical ? untitled.figureSize().x : untitled.figureSize().y);
        const image::Image figure =
            titled.compose(pictureFor(titled, glm::vec4(0, 0, 0, 1)), glm::vec4(0, 0, 0, 1));
        // Ink beyond the labels: right of the widest label, or below the labels.
        const image::ImageRegion bar = titled.barRegion(0);
        const LabelFont font = LabelFont::forImage(320, 240);
        int ink = 0;
        for (int y = 0; y < figure.height(); ++y)
            for (int x = 0; x < figure.width(); ++x) {
                const bool beyond = vertical
                                        ? x > bar.x + bar.width + 12 + font.textWidth("-0.10")
                                        : y > bar.y + bar.height + 8 + font.height();
                ink += beyond && figure.pixel(x, y).r > 0.5f ? 1 : 0;
            }
        EXPECT_GT(ink, 60) << "position " << int(position);
    }
}

TEST(ColorLegend, imagesSmallerThanTheLegendGetWhatFits) {
    for (const LegendPosition position : {LegendPosition::Right, LegendPosition::Bottom}) {
        const ColorLegend legend = legendOf(magma(), position, 3, 2);
        EXPECT_EQ(legend.dataRegion().width, 3);
        EXPECT_EQ(legend.dataRegion().height, 2);
        const image::Image figure = legend.compose(pictureFor(legend, glm::vec4(1.0f)),
                                                   glm::vec4(0.0f));
        EXPECT_EQ(figure.statistics().nonFinitePixels, 0U);
    }
}

TEST(ColorLegend, badLayoutsAreRefused) {
    const auto transfer = magma();
    EXPECT_EQ(errorOf<DataError>([] { ColorLegend({}, {}, 64, 64); }),
              "colour legend: no colour bar to draw");
    EXPECT_EQ(errorOf<DataError>([&] {
                  ColorLegend({barOf(transfer)}, {LegendPosition::Right, 1}, 64, 64);
              }),
              "colour legend: the tick count must be from 2 to 20, got 1");
}

TEST(ColorLegend, positionsAreNamed) {
    EXPECT_EQ(parseLegendPosition("bottom"), LegendPosition::Bottom);
    EXPECT_EQ(errorOf<DataError>([] { parseLegendPosition("middle"); }),
              "legend position must be right, left, top or bottom, got 'middle'");
}

// A FILE_RAW VolumeData of three voxels from `low` to `high`.
nodes::VolumeData::Ptr rawVolume(const std::string& name, float low, float high) {
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
}

TEST(ColorBar, titlesSayWhatAndInWhichUnit) {
    EXPECT_EQ(ColorBar::titleOf("Temperature", "K"), "Temperature (K)");
    EXPECT_EQ(ColorBar::titleOf("Temperature", ""), "Temperature");
    EXPECT_EQ(ColorBar::titleOf("", "m/s"), "m/s");
    EXPECT_EQ(ColorBar::titleOf("", ""), "");
}

TEST(ColorBar, aSceneGivesItsTransferFunctionAndDataRange) {
    nodes::registerNodeTypes();
    const auto root = sg::Separator::create();
    const auto transfer = magma();
    root->addChild(transfer);
    root->addChild(rawVolume("distance.raw", -0.15f, 0.15f));
    std::vector<ColorBar> bars = ColorBar::ofScene(*root);
    ASSERT_EQ(bars.size(), 1u);
    EXPECT_EQ(bars[0].range, glm::vec2(-0.15f, 0.15f));
    EXPECT_EQ(bars[0].title, "");
    transfer->title.setValue("Distance");
    transfer->units.setValue("mm");
    EXPECT_EQ(ColorBar::ofScene(*root)[0].title, "Distance (mm)");
    EXPECT_EQ(errorOf<DataError>([] { ColorBar::ofScene(*sg::Separator::create()); }),
              "colour legend: the scene has no TransferFunction");
}

TEST(ColorBar, aSceneGivesWhatItsSplatNodesDrawOneBarPerScale) {
    // A function and a volume that no splat node draws come first in the file, as a shared
    // mask volume or a function kept for later would: the bars are of what is drawn.
    nodes::registerNodeTypes();
    auto drawn = nodes::TransferFunction::create();
    drawn->preset.setValue(nodes::ColorPreset::Viridis);
    const auto unused = sg::Separator::create();
    unused->addChild(magma());
    unused->addChild(rawVolume("unused.raw", -0.15f, 0.15f));
    const auto shown = sg::Separator::create();
    shown->addChild(drawn);
    shown->addChild(rawVolume("shown.raw", 2.0f, 10.0f));
    shown->addChild(nodes::TextureSplat::create());
    shown->addChild(nodes::TextureSplat::create()); // the same scale: the same bar
    const auto other = sg::Separator::create();
    auto second = magma();
    second->title.setValue("Wind");
    other->addChild(second);
    other->addChild(rawVolume("other.raw", 0.0f, 30.0f));
    other->addChild(nodes::TextureSplat::create());
    const auto root = sg::Separator::create();
    root->addChild(unused);
    root->addChild(shown);
    root->addChild(other);

    const std::vector<ColorBar> bars = ColorBar::ofScene(*root);
    ASSERT_EQ(bars.size(), 2u);
    EXPECT_EQ(bars[0].range, glm::vec2(2.0f, 10.0f));
    EXPECT_EQ(bars[0].colorMap(0.25f), drawn->colorAt(0.25f));
    EXPECT_EQ(bars[1].range, glm::vec2(0.0f, 30.0f));
    EXPECT_EQ(bars[1].title, "Wind");
}

TEST(ColorBar, vectorSplatsLabelTheQuantityTheyColourBy) {
    nodes::registerNodeTypes();
    const auto transfer = magma();
    auto vectors = nodes::VolumeData::create();
    vectors->source.setValue(nodes::VolumeSource::Tornado);
    vectors->resolution.setValue(glm::vec3(8.0f));
    auto colors = rawVolume("colors.raw", 5.0f, 7.0f);
    colors->setName("temperature");
    const auto splat = nodes::VectorSplat::create();
    const auto root = sg::Separator::create();
    root->addChild(transfer);
    root->addChild(vectors);
    root->addChild(splat);

    splat->colorMode.setValue(nodes::VectorColorMode::Position);
    splat->positionRange.setValue(glm::vec2(0.0f, 12.0f));
    std::vector<ColorBar> bars = ColorBar::ofScene(*root);
    ASSERT_EQ(bars.size(), 1u);
    EXPECT_EQ(bars[0].range, glm::vec2(0.0f, 12.0f));
    EXPECT_EQ(bars[0].title, "z");

    splat->colorMode.setValue(nodes::VectorColorMode::Scalar);
    splat->colorData.setValue(colors);
    bars = ColorBar::ofScene(*root);
    ASSERT_EQ(bars.size(), 1u);
    EXPECT_EQ(bars[0].range, glm::vec2(5.0f, 7.0f));
    EXPECT_EQ(bars[0].title, "temperature");

    splat->colorMode.setValue(nodes::VectorColorMode::Magnitude);
    bars = ColorBar::ofScene(*root);
    ASSERT_EQ(bars.size(), 1u);
    EXPECT_EQ(bars[0].title, "magnitude");
    EXPECT_GT(bars[0].range.y, bars[0].range.x);
    transfer->title.setValue("Wind speed");
    EXPECT_EQ(ColorBar::ofScene(*root)[0].title, "Wind speed") << "the function's title wins";

    splat->colorMode.setValue(nodes::VectorColorMode::Constant);
    EXPECT_TRUE(ColorBar::ofScene(*root).empty()) << "one colour: no bar";
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

} // namespace
} // namespace texsplat::annotation
