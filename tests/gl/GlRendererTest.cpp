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

#include <gtest/gtest.h>

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

} // namespace
} // namespace texsplat::nodes
