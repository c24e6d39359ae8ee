// Stiff and extreme inputs through the GL splat renderers (docs/design.md, "Numerics": no NaN
// pixel, ever): opacities per unit length from 1e-8 to 1e8, data values of ±1e30, 1e-30 and near
// the float limit, NaN and infinite voxels. Each scene goes through the nodes (raw file,
// VolumeData, TransferFunction, splat node) and is drawn by the paper's texture splat, the texture
// splat with the Gaussian kernel and the polygonal Gaussian splat. Where the result is predictable
// it is checked: an optically thick slab is opaque and shows the medium's colour, a nearly
// transparent one adds up its emission, values beyond the range classify like the range's ends.

#include "SplatTestSupport.h"
#include "nodes/GaussianSplat.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawHeader.h"
#include "scenegraph/Log.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

// A cube of kSlab³ unit voxels seen along −z by an orthographic camera, kImageSize² pixels.
constexpr int kSlab = 8;
constexpr std::size_t kSlabVoxels = std::size_t{kSlab} * kSlab * kSlab;
constexpr int kImageSize = 32;
// The colour S of every medium here; emission C = S·(τ + emission).
const glm::vec3 kColor(1.0f, 0.5f, 0.25f);

enum class Renderer { PaperTexture, GaussianTexture, PolygonalGaussian };

struct RendererCase {
    Renderer renderer;
    const char* name;
    // Relative tolerance of the emission sum at the slab's centre: the ripple of the footprints'
    // lattice sum, which depends on where the pixels fall (figure-2 layers in SplatBatchTest:
    // paper kernel −0.15 %..+0.23 %, textured Gaussian −4.3 %..+1.9 %, polygonal Gaussian
    // −16 %..+14 %).
    double sumTolerance;
};

const std::vector<RendererCase> kRenderers{
    {Renderer::PaperTexture, "TextureSplat PAPER", 0.005},
    {Renderer::GaussianTexture, "TextureSplat GAUSSIAN", 0.05},
    {Renderer::PolygonalGaussian, "GaussianSplat", 0.2},
};

ScalarSplat::Ptr makeSplat(Renderer renderer) {
    switch (renderer) {
    case Renderer::PaperTexture:
        return TextureSplat::create();
    case Renderer::GaussianTexture: {
        TextureSplat::Ptr splat = TextureSplat::create();
        splat->kernel.setValue(SplatKernel::Gaussian);
        return splat;
    }
    case Renderer::PolygonalGaussian:
        return GaussianSplat::create();
    }
    return nullptr;
}

// A kSlab³ grid of voxel values value(i, j, k), as a raw file.
std::string slabFile(const std::string& name, const std::function<float(int, int, int)>& value) {
    volume::DenseGrid<float> grid{volume::GridGeometry(glm::i64vec3(kSlab))};
    for (int k = 0; k < kSlab; ++k) {
        for (int j = 0; j < kSlab; ++j) {
            for (int i = 0; i < kSlab; ++i) {
                grid.setValue({i, j, k}, value(i, j, k));
            }
        }
    }
    return test::writeTestVolume("extremes_" + name, grid);
}

std::string constantSlabFile(const std::string& name, float value) {
    return slabFile(name, [value](int, int, int) { return value; });
}

// Colour kColor everywhere; opacity τ per unit length interpolated from `opacities` at t = 0
// and t = 1 over `range`; `emission` added glow.
TransferFunction::Ptr medium(const glm::vec2& range, const glm::vec2& opacities, float emission) {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(range);
    transfer->colorValues.setValue({0.0f, 1.0f});
    transfer->colors.setValue({kColor, kColor});
    transfer->opacityValues.setValue({0.0f, 1.0f});
    transfer->opacities.setValue({opacities.x, opacities.y});
    transfer->emission.setValue(emission);
    return transfer;
}

test::RenderedFrame renderSlab(const TransferFunction::Ptr& transfer, const std::string& path,
                               const ScalarSplat::Ptr& splat) {
    OrthographicCamera::Ptr camera = OrthographicCamera::create();
    const sg::Separator::Ptr root = test::framedScene(
        camera, {transfer, test::fileVolume(VolumeSource::FileRaw, path), splat});
    return test::renderFrame(*root, kImageSize, kImageSize);
}

// Mean of the 2 x 2 pixels at the image centre: the middle of the slab, > 2 voxels from its
// sides, where the lattice sum of the footprints is flat.
glm::dvec4 centre(const image::Image& image) {
    return image.statistics({kImageSize / 2 - 1, kImageSize / 2 - 1, 2, 2}).mean;
}

// `value` with 7 significant digits, for the test's recorded properties.
std::string formatted(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", value);
    return text;
}

bool samePixels(const image::Image& a, const image::Image& b) {
    return a.pixels() == b.pixels();
}

// Opacity per unit length τ from 1e-8 to 1e8 over the 8-voxel-deep slab (optical depths 8e-8 to
// 8e8), with emission 1: every image finite, alpha in [0, 1]; at τ = 1e8 the slab is opaque
// and shows S·(τ + 1)/τ = S; at τ = 1e-8 it is transparent and adds up C·8 = S·8 with alpha
// τ·8. Also through an octree cut (maxSplats), whose nodes average the extreme media.
TEST(SplatExtremes, opacityPerUnitLengthFromTinyToHugeGivesFiniteImages) {
    test::sharedContext();
    const std::string path = constantSlabFile("constant", 1.0f);
    for (const RendererCase& renderer : kRenderers) {
        for (bool octreeCut : {false, true}) {
            for (float tau : {1e-8f, 1e-4f, 1.0f, 1e4f, 1e8f}) {
                const std::string what = std::string(renderer.name) +
                                         (octreeCut ? ", octree cut" : "") +
                                         ", tau " + std::to_string(tau);
                SCOPED_TRACE(what);
                ScalarSplat::Ptr splat = makeSplat(renderer.renderer);
                if (octreeCut) {
                    splat->maxSplats.setValue(50);
                }
                const test::RenderedFrame frame =
                    renderSlab(medium({0.0f, 1.0f}, {tau, tau}, 1.0f), path, splat);
                test::expectFiniteWithAlphaInRange(frame.image, what);
                EXPECT_GT(frame.statistics.splats, 0u);
                if (octreeCut) {
                    EXPECT_LE(frame.statistics.splats, 50u);
                    continue;
                }
                EXPECT_EQ(frame.statistics.splats, kSlabVoxels);
                const glm::dvec4 middle = centre(frame.image);
                if (tau == 1e8f) {
                    EXPECT_NEAR(middle.a, 1.0, 1e-6);
                    for (int channel = 0; channel < 3; ++channel) {
                        EXPECT_NEAR(middle[channel], kColor[channel], 1e-5 * kColor[channel]);
                    }
                    ::testing::Test::RecordProperty(
                        std::string(renderer.name) + "_opaque_centre_red_alpha",
                        formatted(middle.r) + " " + formatted(1.0 - middle.a));
                }
                if (tau == 1e-8f) {
                    const double depth = kSlab;
                    EXPECT_NEAR(middle.a, tau * depth, renderer.sumTolerance * tau * depth);
                    for (int channel = 0; channel < 3; ++channel) {
                        EXPECT_NEAR(middle[channel], kColor[channel] * depth,
                                    renderer.sumTolerance * kColor[channel] * depth);
                    }
                    ::testing::Test::RecordProperty(
                        std::string(renderer.name) + "_transparent_centre_red_alpha",
                        formatted(middle.r) + " " + formatted(middle.a));
                }
            }
        }
    }
}

// Values far beyond the range classify like its ends, whatever their size: a slab of 1e30 draws
// exactly what a slab of 1 draws; one of -1e30 classifies to nothing (no splat, black); 1e-30 on
// the range [0, 1e-30] is its top end again. A mix of ±1e30, ±1e-30, a denormal, zero and
// values near the float limit on ranges as wide as ±3e38 stays finite.
TEST(SplatExtremes, hugeAndTinyDataValuesClassifyLikeTheRangeEnds) {
    test::sharedContext();
    const std::string one = constantSlabFile("one", 1.0f);
    const std::string huge = constantSlabFile("huge", 1e30f);
    const std::string hugeNegative = constantSlabFile("huge_negative", -1e30f);
    const std::string tiny = constantSlabFile("tiny", 1e-30f);
    const std::vector<float> values{1e30f,  -1e30f, 1e-30f,
                                    -1e-30f, 1e-45f, 0.0f,
                                    3e38f,  -3e38f, std::numeric_limits<float>::max()};
    const std::string mixed = slabFile("mixed", [&values](int i, int j, int k) {
        return values[static_cast<std::size_t>(i + 2 * j + 3 * k) % values.size()];
    });
    const glm::vec2 opacityRamp(0.0f, 2.0f);
    for (const RendererCase& renderer : kRenderers) {
        SCOPED_TRACE(renderer.name);
        const test::RenderedFrame reference =
            renderSlab(medium({0.0f, 1.0f}, opacityRamp, 0.0f), one, makeSplat(renderer.renderer));
        test::expectFiniteAndNotEmpty(reference.image, "value 1");

        const test::RenderedFrame above =
            renderSlab(medium({0.0f, 1.0f}, opacityRamp, 0.0f), huge, makeSplat(renderer.renderer));
        EXPECT_TRUE(samePixels(above.image, reference.image)) << "1e30 on [0, 1]";
        EXPECT_EQ(above.statistics.splats, reference.statistics.splats);

        const test::RenderedFrame below = renderSlab(medium({0.0f, 1.0f}, opacityRamp, 0.0f),
                                                     hugeNegative, makeSplat(renderer.renderer));
        EXPECT_EQ(below.statistics.splats, 0u) << "-1e30 on [0, 1]";
        EXPECT_EQ(below.image.statistics().maximum, glm::dvec4(0.0)) << "-1e30 on [0, 1]";

        const test::RenderedFrame tinyTop = renderSlab(medium({0.0f, 1e-30f}, opacityRamp, 0.0f),
                                                       tiny, makeSplat(renderer.renderer));
        EXPECT_TRUE(samePixels(tinyTop.image, reference.image)) << "1e-30 on [0, 1e-30]";

        for (const glm::vec2& range : {glm::vec2(0.0f, 1.0f), glm::vec2(-1e30f, 1e30f),
                                       glm::vec2(-3e38f, 3e38f), glm::vec2(0.0f, 1e-30f)}) {
            for (float glow : {0.0f, 1.0f}) {
                const std::string what = "mixed values on [" + std::to_string(range.x) + ", " +
                                         std::to_string(range.y) + "], emission " +
                                         std::to_string(glow);
                const test::RenderedFrame frame = renderSlab(medium(range, opacityRamp, glow),
                                                             mixed, makeSplat(renderer.renderer));
                test::expectFiniteWithAlphaInRange(frame.image, what);
                EXPECT_GT(frame.statistics.splats, 0u) << what;
            }
        }
    }
}

// Writes a kSlab³ float32 raw file whose voxels hold `bits` (IEEE 754 patterns), so that NaNs
// of either sign and payload reach the file as they are.
std::string rawBitsFile(const std::string& name, const std::vector<std::uint32_t>& bits) {
    volume::RawHeader header;
    header.dims = glm::i64vec3(kSlab);
    const std::string path = ::testing::TempDir() + "texsplat_render_extremes_" + name + ".raw";
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << header.format();
    for (const std::uint32_t word : bits) {
        const unsigned char bytes[4] = {
            static_cast<unsigned char>(word), static_cast<unsigned char>(word >> 8),
            static_cast<unsigned char>(word >> 16), static_cast<unsigned char>(word >> 24)};
        out.write(reinterpret_cast<const char*>(bytes), 4);
    }
    EXPECT_TRUE(out.good()) << path;
    return path;
}

std::uint32_t bitsOf(float value) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// NaN (quiet, signalling, negative) and ±Inf voxels mixed into a slab of 1: the reader makes
// them empty with one warning, and the image is exactly that of the slab with 0 (which this
// transfer function leaves empty) in their place, for every renderer and for stiff media.
// Many layers of light near the float limit (emission 3e38): GL's float blending added them up
// to +Inf, and an opaque layer in front multiplied that by 0 (NaN pixels; the read-back's clamp
// leaves NaN). GL draws light scaled by 2^-64 and the read-back scales it back, so the sum stays
// finite, and the opaque front layer hides what is behind it.
TEST(SplatExtremes, manyLayersOfLightNearTheFloatLimitBehindAnOpaqueOneStayFinite) {
    test::sharedContext();
    const std::string path =
        slabFile("bright", [](int, int, int k) { return k == kSlab - 1 ? 1.0f : 0.0f; });
    for (const RendererCase& renderer : kRenderers) {
        SCOPED_TRACE(renderer.name);
        const test::RenderedFrame frame = renderSlab(medium({0.0f, 1.0f}, {1e-3f, 1e8f}, 3e38f),
                                                     path, makeSplat(renderer.renderer));
        test::expectFiniteWithAlphaInRange(frame.image, renderer.name);
        EXPECT_NEAR(centre(frame.image).a, 1.0, 1e-6);
    }
}

TEST(SplatExtremes, nanAndInfiniteVoxelsAreEmptyAndLeaveTheImageFinite) {
    test::sharedContext();
    const std::vector<std::uint32_t> nonFinite{0x7fc00000u, 0x7f800001u, 0xffc00000u,
                                               0x7f800000u, 0xff800000u};
    std::vector<std::uint32_t> withNan;
    std::vector<std::uint32_t> withZero;
    std::size_t nonFiniteCount = 0;
    for (std::size_t voxel = 0; voxel < kSlabVoxels; ++voxel) {
        if (voxel % 3 == 0) {
            withNan.push_back(nonFinite[(voxel / 3) % nonFinite.size()]);
            withZero.push_back(bitsOf(0.0f));
            ++nonFiniteCount;
        } else {
            withNan.push_back(bitsOf(1.0f));
            withZero.push_back(bitsOf(1.0f));
        }
    }
    const std::string nanPath = rawBitsFile("nan", withNan);
    const std::string zeroPath = rawBitsFile("zero", withZero);
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&warnings](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning) {
            warnings.emplace_back(message);
        }
    });
    for (const RendererCase& renderer : kRenderers) {
        for (float tau : {1e-8f, 1.0f, 1e8f}) {
            const std::string what = std::string(renderer.name) + ", tau " + std::to_string(tau);
            SCOPED_TRACE(what);
            const TransferFunction::Ptr transfer = medium({0.0f, 1.0f}, {0.0f, tau}, 0.0f);
            const test::RenderedFrame withHoles =
                renderSlab(transfer, nanPath, makeSplat(renderer.renderer));
            const test::RenderedFrame reference =
                renderSlab(transfer, zeroPath, makeSplat(renderer.renderer));
            test::expectFiniteWithAlphaInRange(withHoles.image, what);
            test::expectFiniteAndNotEmpty(withHoles.image, what);
            EXPECT_EQ(withHoles.statistics.splats, kSlabVoxels - nonFiniteCount);
            EXPECT_EQ(withHoles.statistics.splats, reference.statistics.splats);
            EXPECT_TRUE(samePixels(withHoles.image, reference.image));
        }
    }
    setLogSink(previous);
    ASSERT_FALSE(warnings.empty());
    EXPECT_EQ(warnings[0], nanPath + ": " + std::to_string(nonFiniteCount) +
                               " voxels are NaN or infinite; treated as empty");
}

} // namespace
} // namespace texsplat::nodes
