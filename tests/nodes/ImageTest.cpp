#include "nodes/image/Image.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>

using texsplat::DataError;
using texsplat::image::Image;
using texsplat::image::ImageRegion;
using texsplat::image::Pixels;

namespace {

template <typename Function>
std::string dataErrorMessage(Function&& function) {
    try {
        function();
    } catch (const DataError& e) {
        return e.what();
    }
    return "no DataError";
}

} // namespace

TEST(Image, startsTransparentBlackWithoutDepth) {
    const Image image(3, 2);
    EXPECT_EQ(image.width(), 3);
    EXPECT_EQ(image.height(), 2);
    EXPECT_EQ(image.pixelCount(), 6u);
    EXPECT_FALSE(image.hasDepth());
    EXPECT_TRUE(image.depths().empty());
    EXPECT_EQ(Image(1, 1).depthData(), nullptr);
    for (const glm::vec4& pixel : image.pixels())
        EXPECT_EQ(pixel, glm::vec4(0.0f));
}

TEST(Image, rejectsEmptyAndHugeSizes) {
    EXPECT_EQ(dataErrorMessage([] { Image(0, 5); }),
              "image size 0x5 is empty: width and height must be at least 1");
    EXPECT_EQ(dataErrorMessage([] { Image(4, -1); }),
              "image size 4x-1 is empty: width and height must be at least 1");
    EXPECT_EQ(dataErrorMessage([] { Image(1 << 15, 1 << 14); }),
              "image size 32768x16384 is too large: at most 268435456 pixels");
}

TEST(Image, storesRowsTopFirstAndFillsInOneGo) {
    Image image(2, 3);
    image.setPixel(1, 0, {1.0f, 2.0f, 3.0f, 0.5f});
    EXPECT_EQ(image.pixel(1, 0), glm::vec4(1.0f, 2.0f, 3.0f, 0.5f));
    EXPECT_EQ(image.pixels()[1], glm::vec4(1.0f, 2.0f, 3.0f, 0.5f));
    image.setPixel(0, 2, glm::vec4(7.0f));
    EXPECT_EQ(image.pixels()[4], glm::vec4(7.0f));
    image.data()[5] = glm::vec4(0.5f);
    EXPECT_EQ(image.pixel(1, 2), glm::vec4(0.5f));
    image.fill({0.0f, 0.0f, 0.0f, 1.0f});
    EXPECT_EQ(image.pixel(1, 1), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
}

TEST(Image, unclearedHasTheSizeAndChecksOfAClearedOne) {
    Image image = Image::uncleared(3, 2);
    EXPECT_EQ(image.width(), 3);
    EXPECT_EQ(image.height(), 2);
    EXPECT_EQ(image.pixelCount(), 6u);
    EXPECT_FALSE(image.hasDepth());
    image.fill(glm::vec4(0.5f));
    EXPECT_EQ(image.pixel(2, 1), glm::vec4(0.5f));
    EXPECT_EQ(dataErrorMessage([] { Image::uncleared(3, 0); }),
              "image size 3x0 is empty: width and height must be at least 1");
    EXPECT_EQ(dataErrorMessage([] { Image::uncleared(1 << 15, 1 << 14); }),
              "image size 32768x16384 is too large: at most 268435456 pixels");
}

TEST(Image, takesAndGivesItsPixelsWithoutACopy) {
    Pixels pixels(6, glm::vec4(0.25f));
    pixels[5] = glm::vec4(1.0f);
    const glm::vec4* storage = pixels.data();
    Image image(3, 2, std::move(pixels));
    EXPECT_EQ(image.pixel(2, 1), glm::vec4(1.0f));
    EXPECT_EQ(image.pixels().data(), storage);
    image.addDepth(1.0f);
    const Pixels taken = std::move(image).takePixels();
    EXPECT_EQ(taken.data(), storage);
    EXPECT_EQ(image.width(), 0); // NOLINT(bugprone-use-after-move): left empty, as documented
    EXPECT_FALSE(image.hasDepth());
    EXPECT_EQ(dataErrorMessage([] { Image(3, 2, Pixels(5)); }),
              "image size 3x2 needs 6 pixels, got 5");
    EXPECT_EQ(dataErrorMessage([] { Image(0, 2, {}); }),
              "image size 0x2 is empty: width and height must be at least 1");
}

TEST(Image, depthStartsAtInfinityAndIsPerPixel) {
    Image image(2, 2);
    image.addDepth();
    ASSERT_TRUE(image.hasDepth());
    EXPECT_EQ(image.depth(1, 1), std::numeric_limits<float>::infinity());
    image.setDepth(1, 0, 2.5f);
    EXPECT_EQ(image.depths()[1], 2.5f);
    image.depthData()[3] = -1.0f;
    EXPECT_EQ(image.depth(1, 1), -1.0f);
    image.addDepth(0.0f);
    EXPECT_EQ(image.depth(1, 0), 0.0f);
}

TEST(Image, flipVerticallyReversesRowsOfColorAndDepth) {
    Image image(2, 3);
    image.addDepth();
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 2; ++x) {
            image.setPixel(x, y, glm::vec4(static_cast<float>(10 * y + x)));
            image.setDepth(x, y, static_cast<float>(y));
        }
    }
    image.flipVertically();
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 2; ++x) {
            EXPECT_EQ(image.pixel(x, y), glm::vec4(static_cast<float>(10 * (2 - y) + x)));
            EXPECT_EQ(image.depth(x, y), static_cast<float>(2 - y));
        }
    }
}

TEST(Image, statisticsOverRegion) {
    Image image(4, 3);
    image.setPixel(1, 1, {0.2f, 0.4f, 0.0f, 1.0f});
    image.setPixel(2, 1, {0.4f, -0.4f, 2.0f, 0.5f});
    image.setPixel(3, 2, glm::vec4(100.0f)); // outside the region below
    const Image::Statistics stats = image.statistics({1, 1, 2, 1});
    EXPECT_EQ(stats.finitePixels, 2u);
    EXPECT_EQ(stats.nonFinitePixels, 0u);
    EXPECT_NEAR(stats.mean.r, 0.3, 1e-7);
    EXPECT_NEAR(stats.mean.g, 0.0, 1e-7);
    EXPECT_NEAR(stats.mean.b, 1.0, 1e-7);
    EXPECT_NEAR(stats.mean.a, 0.75, 1e-7);
    EXPECT_NEAR(stats.minimum.g, -0.4, 1e-7);
    EXPECT_NEAR(stats.maximum.b, 2.0, 1e-7);

    const Image::Statistics whole = image.statistics();
    EXPECT_EQ(whole.finitePixels, 12u);
    EXPECT_NEAR(whole.maximum.r, 100.0, 1e-7);
    EXPECT_NEAR(whole.mean.a, (1.0 + 0.5 + 100.0) / 12.0, 1e-7);
}

TEST(Image, statisticsCountNonFinitePixelsAndLeaveThemOut) {
    Image image(3, 1);
    image.setPixel(0, 0, {0.5f, 0.5f, 0.5f, 1.0f});
    image.setPixel(1, 0, {std::nanf(""), 0.0f, 0.0f, 1.0f});
    image.setPixel(2, 0, {0.0f, 0.0f, std::numeric_limits<float>::infinity(), 1.0f});
    const Image::Statistics stats = image.statistics();
    EXPECT_EQ(stats.finitePixels, 1u);
    EXPECT_EQ(stats.nonFinitePixels, 2u);
    EXPECT_EQ(stats.mean, glm::dvec4(0.5, 0.5, 0.5, 1.0));
    EXPECT_EQ(stats.maximum, glm::dvec4(0.5, 0.5, 0.5, 1.0));
}

TEST(Image, statisticsWithoutFinitePixelsAreNaN) {
    Image image(1, 1);
    image.setPixel(0, 0, glm::vec4(std::nanf("")));
    const Image::Statistics stats = image.statistics();
    EXPECT_EQ(stats.finitePixels, 0u);
    EXPECT_EQ(stats.nonFinitePixels, 1u);
    EXPECT_TRUE(std::isnan(stats.mean.r));
    EXPECT_TRUE(std::isnan(stats.minimum.a));
}

TEST(Image, regionOutsideTheImageIsDataError) {
    const Image image(8, 8);
    EXPECT_TRUE(image.contains({0, 0, 8, 8}));
    EXPECT_FALSE(image.contains({0, 0, 0, 8}));
    EXPECT_FALSE(image.contains({-1, 0, 2, 2}));
    EXPECT_FALSE(image.contains({1, 0, std::numeric_limits<int>::max(), 2}));
    EXPECT_EQ(dataErrorMessage([&] { image.statistics({4, 4, 10, 10}); }),
              "region 4,4 10x10 is not inside the 8x8 image");
}
