#include "nodes/kernel/FootprintTexture.h"

#include "SceneNodesTestSupport.h"
#include "nodes/image/ImageIo.h"
#include "nodes/kernel/CubicKernel.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

using texsplat::kernel::CubicKernel;
using texsplat::kernel::FootprintTexture;
using texsplat::nodes::test::errorOf;

TEST(FootprintTexture, texelsHoldTheFootprintAtTexelCentres) {
    const CubicKernel kernel = CubicKernel::paper();
    const FootprintTexture texture(kernel, 8);
    EXPECT_EQ(texture.texels().size(), 64u);
    // Texel (row 4, column 5) has its centre at (−1.6 + 5.5·0.4, −1.6 + 4.5·0.4) = (0.6, 0.2).
    EXPECT_FLOAT_EQ(texture.texels()[4 * 8 + 5],
                    static_cast<float>(kernel.footprint(std::hypot(0.6, 0.2))));
    EXPECT_NEAR(texture.sample({0.6, 0.2}), kernel.footprint(std::hypot(0.6, 0.2)), 1e-7);
    EXPECT_EQ(texture.sample({1.7, 0.0}), 0.0);
    EXPECT_EQ(texture.texels()[0], 0.0f); // the corner lies outside the support
}

TEST(FootprintTexture, itsReachHoldsEveryPointTheLookupDoesNotReadAsZero) {
    const CubicKernel kernel = CubicKernel::paper();
    const auto farthestNonZero = [](const FootprintTexture& texture) {
        // The lookup on a fine grid over the quad.
        double farthest = 0.0;
        const double extent = texture.extent();
        for (int row = 0; row <= 400; ++row) {
            for (int column = 0; column <= 400; ++column) {
                const double x = -extent + 2.0 * extent * column / 400.0;
                const double y = -extent + 2.0 * extent * row / 400.0;
                if (texture.sample({x, y}) != 0.0) {
                    farthest = std::max(farthest, std::hypot(x, y));
                }
            }
        }
        return farthest;
    };
    // The paper's: the kernel's support 1.556, and a texel's diagonal past it at most.
    const FootprintTexture paper(kernel, 64);
    EXPECT_GE(paper.reach(), farthestNonZero(paper));
    EXPECT_GE(paper.reach(), kernel.support() - 1e-9);
    EXPECT_LE(paper.reach(), kernel.support() + 3.2 / 64 * std::sqrt(2.0));
    // A quad narrower than the support: its corner.
    const FootprintTexture narrow(kernel, 16, 0.8);
    EXPECT_DOUBLE_EQ(narrow.reach(), 0.8 * std::sqrt(2.0));
    EXPECT_GE(narrow.reach(), farthestNonZero(narrow));
    // The polygonal Gaussian's fan: its radius, and a texel's diagonal past it at most.
    const FootprintTexture fan = FootprintTexture::gouraudFan(kernel, 1.6, 3, 7, 64);
    EXPECT_GE(fan.reach(), farthestNonZero(fan));
    EXPECT_LE(fan.reach(), 1.6 + 3.2 / 64 * std::sqrt(2.0));
}

TEST(FootprintTexture, rippleShrinksWithResolutionAndStaysBelowThePapersFlatness) {
    const CubicKernel kernel = CubicKernel::paper();
    const auto r32 = FootprintTexture(kernel, 32).measureLayerRipple(kernel, 24);
    const auto r64 = FootprintTexture(kernel, 64).measureLayerRipple(kernel, 24);
    const auto r128 = FootprintTexture(kernel, 128).measureLayerRipple(kernel, 24);
    // Bilinear interpolation errs by O(h²): halving the texel roughly quarters the error.
    EXPECT_LT(r64.maxError, 0.4 * r32.maxError);
    EXPECT_LT(r128.maxError, 0.4 * r64.maxError);
    // At 64² the texture adds less than a tenth of the paper's one part in 256.
    EXPECT_LT(r64.maxError, 0.1 / 256.0);
    EXPECT_LT(r64.max - r64.min, 1.0 / 256.0);
    EXPECT_NEAR(r64.exactMax, 1.00249, 0.5e-5);
}

TEST(FootprintTexture, eightBitTexelsAndNarrowExtentBreakTheFlatness) {
    const CubicKernel kernel = CubicKernel::paper();
    const FootprintTexture texture(kernel, 64);
    EXPECT_GT(texture.quantizedTo8Bits().measureLayerRipple(kernel, 24).maxError, 1.0 / 256.0);
    // A quad 1.6 voxels wide (half-width 0.8) cuts the footprint off at r = 0.8.
    const auto narrow = FootprintTexture(kernel, 64, 0.8).measureLayerRipple(kernel, 24);
    EXPECT_GT(narrow.max - narrow.min, 0.3);
}

TEST(FootprintTexture, writesLittleEndianPfm) {
    const CubicKernel kernel = CubicKernel::paper();
    const FootprintTexture texture(kernel, 4);
    const std::string path = ::testing::TempDir() + "footprint_test.pfm";
    texture.write(path);
    std::ifstream file(path, std::ios::binary);
    const std::string contents((std::istreambuf_iterator<char>(file)),
                               std::istreambuf_iterator<char>());
    const std::string header = "Pf\n4 4\n-1.0\n";
    ASSERT_EQ(contents.size(), header.size() + 16 * sizeof(float));
    EXPECT_EQ(contents.substr(0, header.size()), header);
    float fifth = 0.0f;
    std::memcpy(&fifth, contents.data() + header.size() + 5 * sizeof(float), sizeof(float));
    EXPECT_EQ(fifth, texture.texels()[5]);
    std::remove(path.c_str());
}

TEST(FootprintTexture, writesExrAndPngWithFInEveryChannel) {
    const CubicKernel kernel = CubicKernel::paper();
    const FootprintTexture texture(kernel, 8);
    // Texel (row 4, column 5) is pixel (5, 8 − 1 − 4): images run from y = +E at the top.
    const float texel = texture.texels()[4 * 8 + 5];
    if (texsplat::image::isExrSupported()) {
        const std::string exr = ::testing::TempDir() + "footprint_test.EXR";
        texture.write(exr);
        const texsplat::image::Image image = texsplat::image::readImage(exr);
        ASSERT_EQ(image.sizeString(), "8x8");
        EXPECT_EQ(image.pixel(5, 3), glm::vec4(texel));
        std::remove(exr.c_str());
    }
    const std::string png = ::testing::TempDir() + "footprint_test.png";
    texture.write(png);
    const texsplat::image::Image image = texsplat::image::readImage(png);
    ASSERT_EQ(image.sizeString(), "8x8");
    // White with alpha f in 8 bits: read back premultiplied, every channel is f to 1/510.
    for (int channel = 0; channel < 4; ++channel)
        EXPECT_NEAR(image.pixel(5, 3)[channel], texel, 0.5 / 255.0 + 1e-6) << channel;
    std::remove(png.c_str());
}

TEST(FootprintTexture, badArgumentsThrowWithClearMessages) {
    const CubicKernel kernel = CubicKernel::paper();
    using texsplat::DataError;
    EXPECT_EQ(errorOf<DataError>([&] { FootprintTexture(kernel, 1); }),
              "footprint texture: resolution 1 must be in [2, 8192]");
    for (const auto& [bad, text] :
         {std::pair{std::nan(""), "nan"}, std::pair{0.0, "0"}, std::pair{8.001, "8.001"},
          std::pair{1e300, "1e+300"}}) {
        const double extent = bad;
        EXPECT_EQ(errorOf<DataError>([&] { FootprintTexture(kernel, 16, extent); }),
                  std::string("footprint texture: extent ") + text + " must be in (0, 8] voxels");
    }
    EXPECT_NO_THROW(FootprintTexture(kernel, 2, 8.0));
    const CubicKernel wide = CubicKernel::fromShape(5.0, 8.5, -0.08, 0.002);
    EXPECT_EQ(errorOf<DataError>([&] { FootprintTexture(kernel, 4).measureLayerRipple(wide, 2); }),
              "footprint texture: kernel support 8.5 must be at most 8 voxels to measure the "
              "layer ripple");
}

TEST(FootprintTexture, writeRejectsOtherExtensionsAndWritesNothing) {
    const FootprintTexture texture(CubicKernel::paper(), 4);
    const std::string path = ::testing::TempDir() + "footprint_test.tif";
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { texture.write(path); }),
              path + ": unknown texture extension '.tif' (supported: .pfm, .exr, .png)");
    EXPECT_FALSE(std::ifstream(path).good());
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { texture.write("footprint"); }),
              "footprint: no texture extension (supported: .pfm, .exr, .png)");
    const std::string unwritable = "/nonexistent-directory/texture.pfm";
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { texture.write(unwritable); }),
              unwritable + ": cannot create a file in directory "
              "/nonexistent-directory: No such file or directory");
}
