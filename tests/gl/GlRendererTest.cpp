// The GL backend (render::GlRenderer) draws the backend-neutral Frame that FrameAction collects:
// the same frame object as the CPU backend draws, and batches kept from frame to frame.

#include "SplatTestSupport.h"
#include "nodes/Coordinate3.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/Material.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/Transform.h"
#include "nodes/VolumeData.h"
#include "nodes/image/ImageComparison.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/render/gl/GlRenderer.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace texsplat::nodes {
namespace {

constexpr int kSize = 96;

TransferFunction::Ptr glow(const glm::vec3& color, float opacity) {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->colorValues.setValue({0.0f});
    transfer->colors.setValue({color});
    transfer->opacityValues.setValue({0.0f, 0.1f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.5f * opacity, opacity});
    return transfer;
}

// Two splat nodes sharing space (the second shifted and blue) and an opaque square cutting
// through them, seen in perspective: every part of a frame.
sg::Separator::Ptr twoVolumesAndAMesh(const TextureSplat::Ptr& first,
                                      const TextureSplat::Ptr& second) {
    registerNodeTypes();
    VolumeData::Ptr volume = VolumeData::create();
    volume->source.setValue(VolumeSource::MarschnerLobb);
    volume->resolution.setValue(glm::vec3(20.0f));
    sg::Separator::Ptr shifted = sg::Separator::create();
    Transform::Ptr shift = Transform::create();
    shift->translation.setValue(glm::vec3(0.1f, 0.05f, 0.0f));
    shifted->addChild(shift);
    shifted->addChild(glow(glm::vec3(0.0f, 0.3f, 1.0f), 6.0f));
    shifted->addChild(volume);
    shifted->addChild(second);
    Coordinate3::Ptr corners = Coordinate3::create();
    corners->point.setValue({glm::vec3(-1.0f, 0.4f, -1.0f), glm::vec3(2.0f, 0.4f, -1.0f),
                             glm::vec3(2.0f, 0.6f, 2.0f), glm::vec3(-1.0f, 0.6f, 2.0f)});
    IndexedFaceSet::Ptr square = IndexedFaceSet::create();
    square->coordIndex.setValue({0, 1, 2, 3, -1});
    Material::Ptr red = Material::create();
    red->diffuseColor.setValue({glm::vec3(0.8f, 0.1f, 0.1f)});
    sg::Separator::Ptr mesh = sg::Separator::create();
    mesh->addChild(red);
    mesh->addChild(corners);
    mesh->addChild(square);
    PerspectiveCamera::Ptr camera = PerspectiveCamera::create();
    camera->orientation.setValue(render::rotationLookingAlong({-0.6f, -0.35f, -1.0f}));
    return test::framedScene(camera, {mesh, glow(glm::vec3(1.0f, 0.6f, 0.1f), 8.0f), volume,
                                      first, shifted});
}

TEST(GlRenderer, drawsTheFrameTheCpuBackendDraws) {
    test::sharedContext();
    const sg::Separator::Ptr root =
        twoVolumesAndAMesh(TextureSplat::create(), TextureSplat::create());
    render::FrameAction action(kSize, kSize);
    const render::Frame& frame = action.collect(*root);
    ASSERT_EQ(frame.splats.size(), 2u);
    ASSERT_EQ(frame.meshes.size(), 1u);
    sg::RenderStatistics statistics;
    render::GlRenderer gl;
    const image::Image glImage = gl.draw(frame, statistics);
    const image::Image cpuImage = render::cpu::CpuRenderer(2).draw(frame, statistics);
    test::expectFiniteAndNotEmpty(glImage, "GL");
    const double psnr = image::ImageComparison(glImage, cpuImage).rgb().psnr;
    RecordProperty("CPU vs GL", std::to_string(psnr) + " dB");
    // CpuBackendTest's bound for the GL test scenes (84 dB measured here).
    EXPECT_GE(psnr, 50.0);
}

TEST(GlRenderer, keepsItsBatchesWhileTheSceneKeepsItsFootprints) {
    test::sharedContext();
    const TextureSplat::Ptr first = TextureSplat::create();
    const sg::Separator::Ptr root = twoVolumesAndAMesh(first, TextureSplat::create());
    render::FrameAction action(kSize, kSize);
    render::GlRenderer gl;
    const auto batchesMade = [&] {
        gl.render(action.collect(*root), action.statistics());
        return action.statistics().builds.splatBatches;
    };
    EXPECT_EQ(batchesMade(), 2u);
    EXPECT_EQ(batchesMade(), 0u) << "an unchanged scene draws with the batches it has";
    first->size.setValue(2.0f);
    EXPECT_EQ(batchesMade(), 1u) << "a new footprint, a new batch; the other node keeps its own";
}

TEST(GlRenderer, drawsANodesRefilledSplatListAnew) {
    // A splat node refills last frame's list when that frame is gone (the same object, new
    // splats): the GL batch must upload it again. Frame 2 sees the scene from the other side; it
    // must be what a fresh renderer draws of it.
    test::sharedContext();
    // Footprints of their own (two nodes of one footprint share its batch, which then uploads
    // each list in turn anyway).
    const TextureSplat::Ptr second = TextureSplat::create();
    second->size.setValue(1.5f);
    const sg::Separator::Ptr root = twoVolumesAndAMesh(TextureSplat::create(), second);
    auto* camera = static_cast<PerspectiveCamera*>(root->child(0).get());
    render::FrameAction action(kSize, kSize);
    render::GlRenderer kept;
    const octree::SplatList* list = action.collect(*root).splats[0].list().get();
    const image::Image before = kept.draw(action.frame(), action.statistics());
    camera->orientation.setValue(render::rotationLookingAlong({0.6f, 0.35f, 1.0f}));
    test::frameCamera(*camera, *root); // from the other side: the splats' order changes
    const render::Frame& turned = action.collect(*root);
    EXPECT_EQ(turned.splats[0].list().get(), list) << "the list was refilled, not made anew";
    const image::Image after = kept.draw(turned, action.statistics());
    render::GlRenderer fresh;
    const image::Image expected = fresh.draw(turned, action.statistics());
    EXPECT_GT(image::ImageComparison(before, expected).rgb().rmse, 1e-3) << "the view changed";
    EXPECT_EQ(image::ImageComparison(after, expected).rgb().rmse, 0.0);
}

// A frame larger than the tile size is drawn tile by tile through clip matrices scaled and moved
// onto each tile; the pixels are the same but for rounding (measured: 3.6e-6 of colour, 5.4e-7
// of depth) and a pixel whose centre a mesh edge passes within rounding of, which may fall on the
// other side (one of the 5917 pixels with tiles of 32).
TEST(GlRenderer, drawsAFrameInTilesAsInOnePiece) {
    test::sharedContext();
    const sg::Separator::Ptr root =
        twoVolumesAndAMesh(TextureSplat::create(), TextureSplat::create());
    // 97 x 61 pixels: tiles of 64 (one row), 32 and 7, the last column and row narrower.
    render::FrameAction action(97, 61);
    const render::Frame& frame = action.collect(*root);
    sg::RenderStatistics statistics;
    render::GlRenderer whole;
    const image::Image reference = whole.draw(frame, statistics, true);
    for (const int tileSize : {64, 32, 7}) {
        render::GlRenderer tiled;
        EXPECT_THROW(tiled.setMaxTileSize(-1), DataError);
        tiled.setMaxTileSize(tileSize);
        const image::Image image = tiled.draw(frame, statistics, true);
        ASSERT_EQ(image.width(), reference.width());
        ASSERT_EQ(image.height(), reference.height());
        float colour = 0.0f;
        float depth = 0.0f;
        std::size_t edgePixels = 0;
        for (int y = 0; y < reference.height(); ++y) {
            for (int x = 0; x < reference.width(); ++x) {
                const glm::vec4 d = glm::abs(image.pixel(x, y) - reference.pixel(x, y));
                const float pixelColour = std::max({d.r, d.g, d.b, d.a});
                const float pixelDepth = std::abs(image.depth(x, y) - reference.depth(x, y));
                if (pixelColour > 1e-5f || pixelDepth > 1e-5f) {
                    ++edgePixels;
                    continue;
                }
                colour = std::max(colour, pixelColour);
                depth = std::max(depth, pixelDepth);
            }
        }
        RecordProperty("tiles of " + std::to_string(tileSize),
                       "colour " + std::to_string(colour) + ", depth " + std::to_string(depth) +
                           ", " + std::to_string(edgePixels) + " pixels on a mesh edge");
        EXPECT_LE(edgePixels, 5u) << "tiles of " << tileSize;
    }
    // Each renderer made its two batches once, not once per tile.
    EXPECT_EQ(statistics.builds.splatBatches, 2u * 4u);
}

} // namespace
} // namespace texsplat::nodes
