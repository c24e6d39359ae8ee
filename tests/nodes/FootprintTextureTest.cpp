#include "nodes/kernel/FootprintTexture.h"

#include "nodes/kernel/CubicKernel.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

using texsplat::kernel::CubicKernel;
using texsplat::kernel::FootprintTexture;

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
    texture.writePfm(path);
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

TEST(FootprintTexture, badArgumentsThrowWithClearMessages) {
    const CubicKernel kernel = CubicKernel::paper();
    try {
        FootprintTexture(kernel, 1);
        FAIL();
    } catch (const texsplat::DataError& error) {
        EXPECT_STREQ(error.what(), "footprint texture: resolution 1 must be in [2, 8192]");
    }
    try {
        FootprintTexture(kernel, 16, std::nan(""));
        FAIL();
    } catch (const texsplat::DataError& error) {
        EXPECT_STREQ(error.what(), "footprint texture: extent nan must be a finite number > 0");
    }
    try {
        FootprintTexture(kernel, 4).writePfm("/nonexistent-directory/texture.pfm");
        FAIL();
    } catch (const texsplat::IoError& error) {
        EXPECT_STREQ(error.what(), "/nonexistent-directory/texture.pfm: cannot open for writing");
    }
}
