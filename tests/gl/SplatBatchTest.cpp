#include "nodes/render/gl/SplatBatch.h"

#include "SplatTestSupport.h"
#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/GaussianKernel.h"
#include "nodes/kernel/KernelOptimizer.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/CheckGlError.h"
#include "scenegraph/gl/LightScale.h"

#include <gtest/gtest.h>

#include <vector>

namespace texsplat::render {
namespace {

using test::kLayerVoxels;
using test::kPaperLayerMax;
using test::kPaperLayerMin;
using test::kPixelsPerVoxel;
using test::LayerStatistics;

// The figure-2 constants live in SplatTestSupport.h: the node pipeline's test uses them too.
constexpr int kImageSize = test::kLayerImageSize;

// One layer of voxels with emission `emission` per unit length and no extinction, in slice
// order for a view along −z.
octree::SplatList glowingLayer(float emission) {
    octree::ClassifiedGrid grid({kLayerVoxels, kLayerVoxels, 1}, glm::dvec3(1.0), glm::dvec3(0.0));
    for (std::uint64_t j = 0; j < kLayerVoxels; ++j) {
        for (std::uint64_t i = 0; i < kLayerVoxels; ++i) {
            grid.setVoxel({i, j, 0}, glm::vec3(emission), 0.0f);
        }
    }
    octree::SplatList splats;
    octree::emitVoxelSplats(grid, octree::View::orthographic({0.0, 0.0, -1.0}), splats);
    return splats;
}

render::SplatView layerView() {
    const float pixel = 1.0f / kPixelsPerVoxel;
    return test::topView(-0.5f * pixel, static_cast<float>(kLayerVoxels));
}

// The layer drawn by the GL backend with splats looking like `footprint`.
LayerStatistics renderLayer(const SplatFootprint& footprint) {
    Frame frame;
    frame.width = kImageSize;
    frame.height = kImageSize;
    FrameSplats layer;
    layer.splats = std::make_shared<const octree::SplatList>(glowingLayer(1.0f));
    layer.view = layerView();
    layer.footprint = std::make_shared<const SplatFootprint>(footprint);
    frame.splats.push_back(std::move(layer));
    const image::Image image = test::drawFrame(frame);
    std::vector<float> red;
    for (const glm::vec4& pixel : image.pixels()) {
        red.push_back(pixel.r);
        EXPECT_EQ(pixel.a, 0.0f) << "transparent splats must leave alpha 0";
    }
    return test::layerInteriorStatistics(red, kImageSize);
}

kernel::GaussianKernel sameExtentGaussian() {
    return kernel::KernelOptimizer().fitGaussian(kernel::CubicKernel::paper().support()).kernel;
}

// Squares carrying `texture` (SplatBatch::textured()).
SplatFootprint textured(const kernel::FootprintTexture& texture) {
    SplatFootprint footprint;
    footprint.shape = SplatShape::TexturedSquare;
    footprint.extent = texture.extent();
    footprint.texture = std::make_shared<const kernel::FootprintTexture>(texture);
    return footprint;
}

// The paper's polygonal baseline of `kernel` (SplatBatch::polygonal(), 3 x 7 samples).
SplatFootprint polygonal(const kernel::GaussianKernel& kernel) {
    SplatFootprint footprint;
    footprint.shape = SplatShape::GouraudPolygon;
    footprint.extent = kernel::FootprintTexture::kPaperExtent;
    footprint.kernel = std::make_shared<const kernel::GaussianKernel>(kernel);
    return footprint;
}

TEST(SplatBatch, figure2LayerOfPaperSplatsIsAsFlatAsThePaperReports) {
    test::sharedContext();
    const kernel::CubicKernel cubic = kernel::CubicKernel::paper();
    const kernel::FootprintTexture footprint(cubic, 64);
    const LayerStatistics layer = renderLayer(textured(footprint));
    test::reportLayer("paper cubic, 64x64 float texture", layer);
    EXPECT_NEAR(layer.mean, 1.0, 2e-3);
    EXPECT_NEAR(layer.relativeMax(), kPaperLayerMax, 1e-3 * kPaperLayerMax);
    EXPECT_NEAR(layer.relativeMin(), kPaperLayerMin, 1e-3 * kPaperLayerMin);
    // The GL sum agrees with the CPU model of the same texture (bilinear, clamped) to the
    // precision of llvmpipe's texture filtering weights.
    const kernel::TextureRipple cpu = footprint.measureLayerRipple(cubic, 16);
    EXPECT_NEAR(layer.max, cpu.max, 5e-4);
    EXPECT_NEAR(layer.min, cpu.min, 5e-4);
}

TEST(SplatBatch, figure2GaussianOfTheSameExtentRipplesMore) {
    test::sharedContext();
    const kernel::CubicKernel cubic = kernel::CubicKernel::paper();
    const kernel::GaussianKernel gaussian = sameExtentGaussian();
    EXPECT_EQ(SplatBatch::create(polygonal(gaussian)).templateTriangles(), 21);
    const LayerStatistics cubicLayer = renderLayer(textured(kernel::FootprintTexture(cubic, 64)));
    const LayerStatistics texturedLayer =
        renderLayer(textured(kernel::FootprintTexture(gaussian, 64)));
    const LayerStatistics polygonalLayer = renderLayer(polygonal(gaussian));
    test::reportLayer("textured Gaussian (same extent)", texturedLayer);
    test::reportLayer("polygonal Gaussian, 3 radial x 7 azimuth, Gouraud", polygonalLayer);
    const auto ripple = [](const LayerStatistics& s) { return s.relativeMax() - s.relativeMin(); };
    EXPECT_GT(ripple(texturedLayer), 2.0 * ripple(cubicLayer));
    EXPECT_GT(ripple(polygonalLayer), ripple(texturedLayer));
}

// The paper's point about 8 bits ("one part in 256, or one bit"): the same layer drawn into an
// RGBA8 target, each splat's contribution rounded before it is added.
TEST(SplatBatch, figure2InAnEightBitFramebufferDeviatesByQuantization) {
    test::sharedContext();
    const kernel::CubicKernel cubic = kernel::CubicKernel::paper();
    SplatBatch batch = SplatBatch::textured(kernel::FootprintTexture(cubic, 64));
    // Emission 0.5 keeps the sum in the middle of the 8-bit range. GL draws light scaled by
    // gl::kLightScale (the GL backend's read-back scales it back): the layer glows as much more.
    batch.upload(glowingLayer(0.5f / gl::kLightScale));
    gl::Texture2D color(kImageSize, kImageSize, gl::TextureFormat::RGBA8,
                        {gl::TextureFilter::Nearest, gl::TextureWrap::ClampToEdge, false});
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
    glViewport(0, 0, kImageSize, kImageSize);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    batch.draw(layerView());
    glDisable(GL_BLEND);
    std::vector<float> rgba(static_cast<std::size_t>(kImageSize) * kImageSize * 4);
    glReadPixels(0, 0, kImageSize, kImageSize, GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    gl::checkGlError("figure2InAnEightBitFramebufferDeviatesByQuantization");
    std::vector<float> red;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        red.push_back(rgba[i]);
    }
    const LayerStatistics layer = test::layerInteriorStatistics(red, kImageSize);
    test::reportLayer("paper cubic, 8-bit framebuffer", layer);
    EXPECT_NEAR(layer.mean, 0.5, 0.02);
    // Up to nine splats overlap a pixel, each rounded to 1/255: the deviation is a few levels,
    // well above the kernel's own ripple of 0.4%.
    EXPECT_GT(layer.relativeMax() - layer.relativeMin(), kPaperLayerMax - kPaperLayerMin);
    EXPECT_LT(layer.relativeMax() - layer.relativeMin(), 12.0 / 255.0 / 0.5);
}

TEST(SplatBatch, polygonalRejectsTooFewSamples) {
    test::sharedContext();
    const kernel::GaussianKernel gaussian = sameExtentGaussian();
    try {
        SplatBatch::polygonal(gaussian, 1.6, 1, 7);
        FAIL();
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "polygonal splat: needs at least 2 radial and 3 azimuth samples, got 1 and 7");
    }
}

} // namespace
} // namespace texsplat::render
