#include "nodes/image/ImageComparison.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <cmath>
#include <limits>

using texsplat::DataError;
using texsplat::image::ComparisonOptions;
using texsplat::image::Image;
using texsplat::image::ImageComparison;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfinity = std::numeric_limits<float>::infinity();

Image uniform(int width, int height, const glm::vec4& value) {
    Image image(width, height);
    image.fill(value);
    return image;
}

template <typename Function>
std::string dataErrorMessage(Function&& function) {
    try {
        function();
    } catch (const DataError& e) {
        return e.what();
    }
    return "no DataError";
}

/// The color of a difference-image pixel: viridis's values as they are.
glm::vec3 encoded(const glm::vec4& pixel) { return glm::vec3(pixel); }

/// Within 0.002 of viridis's table entries: t maps to table position 255·t (t = 0.5 lies half
/// a table step from entry 128, whose values the tests quote).
void expectColorNear(const glm::vec3& actual, const glm::vec3& expected, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], 2e-3) << what << " channel " << c;
}

} // namespace

TEST(ImageComparison, identicalImagesHaveZeroErrorAndInfinitePsnr) {
    const Image image = uniform(4, 3, {0.25f, 0.5f, 2.0f, 1.0f});
    const ImageComparison comparison(image, image);
    EXPECT_EQ(comparison.comparedPixels(), 12u);
    EXPECT_EQ(comparison.nonFinitePixels(), 0u);
    EXPECT_EQ(comparison.rgb().rmse, 0.0);
    EXPECT_EQ(comparison.rgb().psnr, std::numeric_limits<double>::infinity());
    EXPECT_EQ(comparison.rgb().maxAbsError, 0.0);
    EXPECT_EQ(comparison.rgb().maxX, 0);
    EXPECT_EQ(comparison.rgb().maxY, 0);
    EXPECT_EQ(comparison.maxPixelError(), 0.0);
}

TEST(ImageComparison, uniformOffsetGivesKnownRmseAndPsnr) {
    const Image reference = uniform(8, 8, {0.5f, 0.5f, 0.5f, 1.0f});
    const Image test = uniform(8, 8, {0.625f, 0.5f, 0.5f, 1.0f}); // exact binary offset 1/8
    const ImageComparison comparison(reference, test);
    EXPECT_DOUBLE_EQ(comparison.channel(0).rmse, 0.125);
    EXPECT_DOUBLE_EQ(comparison.channel(0).psnr, 20.0 * std::log10(8.0)); // 18.0618 dB
    EXPECT_EQ(comparison.channel(1).rmse, 0.0);
    EXPECT_EQ(comparison.channel(3).psnr, std::numeric_limits<double>::infinity());
    // Pooled over R, G, B: mean squared error 0.125² / 3.
    EXPECT_DOUBLE_EQ(comparison.rgb().rmse, 0.125 / std::sqrt(3.0));
    EXPECT_NEAR(comparison.rgb().psnr, 22.8330, 1e-4);
    EXPECT_DOUBLE_EQ(comparison.rgb().maxAbsError, 0.125);
    EXPECT_EQ(comparison.rgb().maxChannel, 0);
    EXPECT_DOUBLE_EQ(comparison.maxPixelError(), 0.125 / std::sqrt(3.0));
}

TEST(ImageComparison, halfThePixelsOffGivesRmseOfTheSquareMean) {
    const Image reference = uniform(4, 4, glm::vec4(0.0f));
    Image test = reference;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            test.setPixel(x, y, {0.0f, 0.0f, 0.0f, 0.2f});
    const ImageComparison comparison(reference, test);
    EXPECT_NEAR(comparison.channel(3).rmse, std::sqrt(0.02), 1e-8); // √(8·0.2² / 16)
    EXPECT_NEAR(comparison.channel(3).psnr, 10.0 * std::log10(1.0 / 0.02), 1e-6); // 16.99 dB
    EXPECT_EQ(comparison.rgb().rmse, 0.0);
}

TEST(ImageComparison, maxAbsErrorReportsWhereAndWhichChannel) {
    const Image reference = uniform(5, 4, glm::vec4(0.5f));
    Image test = reference;
    test.setPixel(3, 1, {0.5f, -0.2f, 0.5f, 0.5f});
    test.setPixel(0, 2, {0.6f, 0.5f, 0.5f, 0.5f});
    const ImageComparison comparison(reference, test);
    EXPECT_NEAR(comparison.rgb().maxAbsError, 0.7, 1e-7);
    EXPECT_EQ(comparison.rgb().maxX, 3);
    EXPECT_EQ(comparison.rgb().maxY, 1);
    EXPECT_EQ(comparison.rgb().maxChannel, 1);
    EXPECT_EQ(comparison.channel(0).maxX, 0);
    EXPECT_EQ(comparison.channel(0).maxY, 2);
    EXPECT_NEAR(comparison.channel(0).maxAbsError, 0.1, 1e-7);
}

TEST(ImageComparison, peakSetsThePsnrScale) {
    const Image reference = uniform(2, 2, glm::vec4(0.0f));
    const Image test = uniform(2, 2, glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
    ComparisonOptions options;
    options.peak = 100.0;
    EXPECT_DOUBLE_EQ(ImageComparison(reference, test, options).rgb().psnr, 40.0);
    options.peak = 0.0;
    EXPECT_EQ(dataErrorMessage([&] { ImageComparison(reference, test, options); }),
              "PSNR peak must be positive and finite, got 0.000000");
}

TEST(ImageComparison, nonFinitePixelsAreCountedAndLeftOut) {
    const Image reference = uniform(4, 2, {0.5f, 0.5f, 0.5f, 1.0f});
    Image test = uniform(4, 2, {0.625f, 0.625f, 0.625f, 1.0f});
    Image brokenReference = reference;
    test.setPixel(0, 0, {kNaN, 0.5f, 0.5f, 1.0f});
    brokenReference.setPixel(3, 1, {0.5f, 0.5f, 0.5f, kInfinity});
    const ImageComparison comparison(brokenReference, test);
    EXPECT_EQ(comparison.nonFinitePixels(), 2u);
    EXPECT_EQ(comparison.comparedPixels(), 6u);
    // The remaining pixels all differ by exactly 1/8: no NaN reaches the numbers.
    EXPECT_DOUBLE_EQ(comparison.rgb().rmse, 0.125);
    EXPECT_DOUBLE_EQ(comparison.channel(3).rmse, 0.0);
    EXPECT_DOUBLE_EQ(comparison.rgb().maxAbsError, 0.125);
    EXPECT_EQ(comparison.rgb().maxX, 1);
    EXPECT_EQ(comparison.rgb().maxY, 0);
}

TEST(ImageComparison, onlyNonFinitePixelsIsDataError) {
    const Image reference = uniform(2, 1, glm::vec4(kNaN));
    EXPECT_EQ(dataErrorMessage([&] { ImageComparison(reference, uniform(2, 1, glm::vec4(0))); }),
              "no pixel to compare: all 2 selected pixels are NaN or infinite in one of the "
              "images");
}

TEST(ImageComparison, sizeMismatchNamesBothSizes) {
    EXPECT_EQ(dataErrorMessage([] { ImageComparison(Image(64, 64), Image(64, 32)); }),
              "image sizes differ: reference 64x64, test 64x32");
}

TEST(ImageComparison, regionRestrictsTheComparison) {
    const Image reference = uniform(6, 6, glm::vec4(0.0f));
    Image test = reference;
    test.setPixel(0, 0, glm::vec4(1.0f));                // outside the region
    test.setPixel(3, 4, {0.5f, 0.0f, 0.0f, 0.0f});      // inside
    ComparisonOptions options;
    options.region = texsplat::image::ImageRegion{2, 3, 2, 2};
    const ImageComparison comparison(reference, test, options);
    EXPECT_EQ(comparison.comparedPixels(), 4u);
    EXPECT_DOUBLE_EQ(comparison.channel(0).rmse, 0.25); // √(0.25 / 4)
    EXPECT_EQ(comparison.rgb().maxX, 3);
    EXPECT_EQ(comparison.rgb().maxY, 4);
    options.region = texsplat::image::ImageRegion{5, 5, 2, 1};
    EXPECT_EQ(dataErrorMessage([&] { ImageComparison(reference, test, options); }),
              "region 5,5 2x1 is not inside the 6x6 image");
}

TEST(ImageComparison, maskSelectsPixels) {
    const Image reference = uniform(2, 2, glm::vec4(0.0f));
    Image test = reference;
    test.setPixel(1, 0, glm::vec4(1.0f));
    test.setPixel(0, 1, {0.5f, 0.0f, 0.0f, 0.0f});
    ComparisonOptions options;
    options.mask = {1, 0, 1, 0};
    const ImageComparison comparison(reference, test, options);
    EXPECT_EQ(comparison.comparedPixels(), 2u);
    EXPECT_DOUBLE_EQ(comparison.channel(0).maxAbsError, 0.5);
    options.mask = {0, 0, 0, 0};
    EXPECT_EQ(dataErrorMessage([&] { ImageComparison(reference, test, options); }),
              "the mask selects no pixel to compare");
    options.mask = {1, 1, 1};
    EXPECT_EQ(dataErrorMessage([&] { ImageComparison(reference, test, options); }),
              "mask has 3 entries, but the 2x2 images have 4 pixels");
}

TEST(ImageComparison, differenceImageMapsErrorOntoViridis) {
    const Image reference = uniform(4, 1, glm::vec4(0.0f));
    Image test = reference;
    test.setPixel(1, 0, {0.1f, 0.1f, 0.1f, 0.0f}); // per-pixel error 0.1
    test.setPixel(2, 0, {0.2f, 0.2f, 0.2f, 0.0f}); // per-pixel error 0.2 = the maximum
    test.setPixel(3, 0, {kNaN, 0.0f, 0.0f, 0.0f});
    ComparisonOptions options;
    options.mask = {0, 1, 1, 1};
    const ImageComparison comparison(reference, test, options);
    EXPECT_NEAR(comparison.maxPixelError(), 0.2, 1e-7);

    const Image automatic = comparison.differenceImage();
    EXPECT_EQ(automatic.pixel(0, 0), glm::vec4(0.0f)); // masked out: transparent
    expectColorNear(encoded(automatic.pixel(1, 0)), {0.127568f, 0.566949f, 0.550556f}, "half");
    expectColorNear(encoded(automatic.pixel(2, 0)), {0.993248f, 0.906157f, 0.143936f}, "top");
    EXPECT_EQ(automatic.pixel(3, 0), glm::vec4(1.0f, 0.0f, 1.0f, 1.0f)); // non-finite
    EXPECT_EQ(automatic.pixel(2, 0).a, 1.0f);

    const Image fixed = comparison.differenceImage(0.4);
    expectColorNear(encoded(fixed.pixel(1, 0)), {0.229739f, 0.322361f, 0.545706f}, "quarter");
    expectColorNear(encoded(fixed.pixel(2, 0)), {0.127568f, 0.566949f, 0.550556f}, "half");
    EXPECT_EQ(dataErrorMessage([&] { comparison.differenceImage(std::nan("")); }),
              "difference image scale must be finite, got nan");
}

TEST(ImageComparison, differenceImageOfEqualImagesIsTheBottomColor) {
    const Image image = uniform(2, 2, glm::vec4(0.3f));
    const Image difference = ImageComparison(image, image).differenceImage();
    for (const glm::vec4& pixel : difference.pixels())
        expectColorNear(encoded(pixel), {0.267004f, 0.004874f, 0.329415f}, "bottom");
}
