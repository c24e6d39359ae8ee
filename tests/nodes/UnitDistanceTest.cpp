// TransferFunction::unitDistance: two grids of the same values at different spacings render
// alike when the opacities are per voxel (unitDistance 0), and do not when they are per world
// unit (the default, the medium's physical extinction). Drawn by the CPU backend.

#include "nodes/NodeTypes.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/image/ImageComparison.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawVolume.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

constexpr int kSize = 96;
constexpr int kVoxels = 20;

// The same smooth blob of values 0..1, `kVoxels` per axis, at `spacing`.
VolumeData::Ptr blob(const std::string& name, double spacing) {
    volume::DenseScalarGrid grid(
        volume::GridGeometry(glm::i64vec3(kVoxels), glm::dvec3(0.0), glm::dvec3(spacing)));
    for (int k = 0; k < kVoxels; ++k) {
        for (int j = 0; j < kVoxels; ++j) {
            for (int i = 0; i < kVoxels; ++i) {
                const glm::vec3 p = (glm::vec3(i, j, k) + 0.5f) / float(kVoxels) - 0.5f;
                grid.setValue({i, j, k}, std::max(0.0f, 1.0f - 2.2f * glm::length(p)));
            }
        }
    }
    const std::string path = ::testing::TempDir() + "texsplat_" + name + ".raw";
    volume::writeRawVolume(path, grid);
    auto volume = VolumeData::create();
    volume->source.setValue(VolumeSource::FileRaw);
    volume->fileName.setValue(path);
    return volume;
}

image::Image render(const TransferFunction::Ptr& transfer, const VolumeData::Ptr& volume) {
    registerNodeTypes();
    auto camera = OrthographicCamera::create();
    camera->orientation.setValue(render::rotationLookingAlong(glm::vec3(-0.5f, -0.3f, -1.0f)));
    const auto root = sg::Separator::create();
    for (const sg::Node::Ptr& node : std::vector<sg::Node::Ptr>{
             camera, transfer, volume, TextureSplat::create()}) {
        root->addChild(node);
    }
    sg::BoundingBoxAction box;
    box.apply(*root);
    camera->viewAll(box.boundingBox(), 1.0f);
    render::FrameAction action(kSize, kSize);
    const render::cpu::CpuRenderer renderer(2);
    return renderer.draw(action.collect(*root), action.statistics(), true);
}

double psnrBetweenSpacings(float unitDistance) {
    const auto transfer = TransferFunction::create();
    transfer->preset.setValue(ColorPreset::Magma);
    transfer->range = glm::vec2(0.0f, 1.0f);
    transfer->opacities.setValue({0.0f, 0.4f});
    transfer->unitDistance = unitDistance;
    const image::Image coarse = render(transfer, blob("unit-distance-coarse", 1.0));
    const image::Image fine = render(transfer, blob("unit-distance-fine", 0.05));
    EXPECT_GT(coarse.statistics().maximum.a, 0.1);
    return image::ImageComparison(coarse, fine).rgb().psnr;
}

TEST(UnitDistance, theSameValuesAtAnotherSpacingLookAlikePerVoxel) {
    // Per world unit (the default), the grid 20 times finer is 20 times thinner optically.
    const double perWorldUnit = psnrBetweenSpacings(1.0f);
    const double perVoxel = psnrBetweenSpacings(0.0f);
    std::cout << "PSNR between spacings 1 and 0.05: unitDistance 1 " << perWorldUnit
              << " dB, unitDistance 0 (one voxel) " << perVoxel << " dB\n";
    EXPECT_LT(perWorldUnit, 25.0);
    EXPECT_GT(perVoxel, 60.0);
}

} // namespace
} // namespace texsplat::nodes
