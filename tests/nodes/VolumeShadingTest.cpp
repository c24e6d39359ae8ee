// Shaded volumes (TransferFunction::shade, as VTK's ShadeOn): the lighting of one sample, the
// gradients of a classified grid, the grid lit per voxel, and what the splats (CPU backend) and
// the ray-cast reference make of a ball: a disk without shading, a lit sphere with it.

#include "nodes/render/ShadedGrid.h"
#include "nodes/render/VolumeLighting.h"
#include "nodes/render/VoxelGradients.h"

#include "nodes/DirectionalLight.h"
#include "nodes/NodeTypes.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/image/ImageComparison.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/RayCastImage.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/volume/DenseGrid.h"
#include "SceneNodesTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/RayCastAction.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace texsplat::render {
namespace {

using nodes::test::errorOf;

VolumeLighting headlight() {
    VolumeLighting lighting;
    lighting.lights = {{glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(1.0f)}};
    lighting.viewDirection = glm::vec3(0.0f, 0.0f, -1.0f);
    return lighting;
}

TEST(VolumeLighting, aSampleIsLitByItsGradientAsVtkShadesIt) {
    const VolumeLighting lighting = headlight();
    const glm::vec3 color(0.5f, 0.25f, 1.0f);
    // No gradient: the ambient part alone.
    EXPECT_EQ(lighting.shade(color, 2.0f, glm::vec3(0.0f)), 0.1f * color);
    // Facing the light and the eye: ambient + diffuse, and the highlight times the extinction.
    const glm::vec3 facing = lighting.shade(color, 2.0f, glm::vec3(0.0f, 0.0f, 3.0f));
    EXPECT_NEAR(facing.r, 0.8f * 0.5f + 0.2f * 2.0f, 1e-6f);
    EXPECT_NEAR(facing.b, 0.8f * 1.0f + 0.2f * 2.0f, 1e-6f);
    // Two-sided: the opposite normal is lit alike.
    EXPECT_EQ(lighting.shade(color, 2.0f, glm::vec3(0.0f, 0.0f, -3.0f)), facing);
    // Edge-on: ambient, and the highlight's |n·h|^10 of n·h = 0.
    EXPECT_EQ(lighting.shade(color, 2.0f, glm::vec3(1.0f, 0.0f, 0.0f)), 0.1f * color);
    // At 60 degrees: diffuse times 1/2, highlight times 2^-10.
    const glm::vec3 tilted =
        lighting.shade(color, 2.0f, glm::vec3(std::sqrt(3.0f) / 2.0f, 0.0f, 0.5f));
    EXPECT_NEAR(tilted.g, 0.1f * 0.25f + 0.7f * 0.5f * 0.25f + 0.2f * 2.0f / 1024.0f, 1e-6f);
    // Glow that absorbs nothing shows no highlight.
    EXPECT_EQ(lighting.shade(color, 0.0f, glm::vec3(0.0f, 0.0f, 1.0f)), 0.8f * color);
}

TEST(VolumeLighting, comesFromTheTransferFunctionAndTheLights) {
    nodes::registerNodeTypes();
    auto transfer = nodes::TransferFunction::create();
    transfer->ambient.setValue(0.25f);
    transfer->specularPower.setValue(4.0f);
    sg::State state;
    nodes::LightElement lights;
    state.modify<nodes::LightElement>() = lights;
    CameraView camera;
    camera.viewDirection = glm::normalize(glm::vec3(1.0f, 0.0f, -1.0f));
    VolumeLighting lighting = VolumeLighting::current(state, camera, *transfer);
    EXPECT_EQ(lighting.ambient, 0.25f);
    EXPECT_EQ(lighting.diffuse, 0.7f);
    EXPECT_EQ(lighting.specularPower, 4.0f);
    ASSERT_EQ(lighting.lights.size(), 1u) << "no light in the scene: the headlight";
    EXPECT_EQ(lighting.lights[0].direction, camera.viewDirection);
    EXPECT_TRUE(lighting.isViewDependent());
    transfer->specularPower.setValue(0.0f);
    EXPECT_EQ(errorOf<DataError>([&] { VolumeLighting::current(state, camera, *transfer); }),
              "TransferFunction: specularPower must be finite and > 0, got 0");
    transfer->specularPower.setValue(10.0f);
    transfer->diffuse.setValue(-1.0f);
    EXPECT_EQ(errorOf<DataError>([&] { VolumeLighting::current(state, camera, *transfer); }),
              "TransferFunction: diffuse must be finite and >= 0, got -1");
}

TEST(VolumeLighting, fixedLightsWithoutHighlightShadeAlikeFromAnyView) {
    VolumeLighting fixed = headlight();
    fixed.lights[0].direction = glm::vec3(0.0f, -1.0f, 0.0f);
    fixed.specular = 0.0f;
    VolumeLighting turned = fixed;
    turned.viewDirection = glm::vec3(1.0f, 0.0f, 0.0f);
    EXPECT_FALSE(fixed.isViewDependent());
    EXPECT_TRUE(fixed.shadesAlike(turned)) << "no highlight, no headlight: the view is moot";
    fixed.specular = 0.2f;
    turned.specular = 0.2f;
    EXPECT_FALSE(fixed.shadesAlike(turned)) << "a highlight moves with the view";
    VolumeLighting brighter = fixed;
    brighter.lights[0].color = glm::vec3(2.0f);
    EXPECT_FALSE(fixed.shadesAlike(brighter));
}

// A classified grid whose extinction rises along x by `slope` per voxel, colour 1.
std::shared_ptr<octree::ClassifiedGrid> rampAlongX(float slope, glm::dvec3 spacing) {
    auto grid = std::make_shared<octree::ClassifiedGrid>(glm::u64vec3(10, 4, 4), spacing,
                                                         glm::dvec3(0.0));
    for (std::uint64_t z = 0; z < 4; ++z)
        for (std::uint64_t y = 0; y < 4; ++y)
            for (std::uint64_t x = 0; x < 10; ++x) {
                grid->setVoxel({x, y, z}, glm::vec3(1.0f), 1.0f + slope * float(x));
            }
    return grid;
}

TEST(VoxelGradients, areCentralDifferencesPerLengthInRootSpace) {
    const auto grid = rampAlongX(0.5f, glm::dvec3(2.0, 1.0, 1.0));
    const VoxelGradients plain(grid, glm::mat4(1.0f));
    // Inside: 0.5 per voxel of 2 units along x, nothing across.
    EXPECT_EQ(plain.at({4, 1, 1}), glm::vec3(0.25f, 0.0f, 0.0f));
    // At the faces τ falls to 0 outside: the faces are surfaces, τ rising into the volume.
    EXPECT_GT(plain.at({4, 0, 1}).y, 0.0f) << "τ below the lowest face is 0";
    EXPECT_LT(plain.at({4, 3, 1}).y, 0.0f) << "... and above the highest one";
    // A Transform that stretches x by 4 spreads the same change over 4 times the length.
    const VoxelGradients stretched(grid, glm::scale(glm::mat4(1.0f), glm::vec3(4.0f, 1.0f, 1.0f)));
    EXPECT_NEAR(stretched.at({4, 1, 1}).x, 0.25f / 4.0f, 1e-7f);
    // A turn of the volume turns its normals.
    const VoxelGradients turned(
        grid, glm::rotate(glm::mat4(1.0f), glm::half_pi<float>(), glm::vec3(0.0f, 0.0f, 1.0f)));
    EXPECT_NEAR(turned.at({4, 1, 1}).y, 0.25f, 1e-6f);
    EXPECT_NEAR(turned.at({4, 1, 1}).x, 0.0f, 1e-6f);
    EXPECT_EQ(plain.memoryBytes(), grid->blockCount() * 512 * sizeof(glm::vec3));
}

TEST(ShadedGrid, litsTheColoursAndKeepsTheExtinctionsAndTheEmptyVoxels) {
    const auto grid = rampAlongX(0.5f, glm::dvec3(1.0));
    grid->setVoxel({9, 3, 3}, glm::vec3(0.0f), 0.0f); // an empty voxel
    const VoxelGradients gradients(grid, glm::mat4(1.0f));
    VolumeLighting lighting = headlight();
    lighting.lights[0].direction = glm::vec3(-1.0f, 0.0f, 0.0f); // along the ramp
    lighting.specular = 0.0f;
    const std::shared_ptr<octree::ClassifiedGrid> lit = shadedGrid(gradients, lighting);
    EXPECT_EQ(lit->dims(), grid->dims());
    EXPECT_EQ(lit->nonEmptyVoxelCount(), grid->nonEmptyVoxelCount());
    EXPECT_TRUE(lit->isEmptyVoxel({9, 3, 3}));
    const glm::vec4 voxel = lit->voxel({4, 1, 1});
    EXPECT_EQ(voxel.w, grid->voxel({4, 1, 1}).w);
    EXPECT_NEAR(voxel.r, 0.1f + 0.7f, 1e-6f) << "the gradient points along the light: full";
}

// A ball of radius 9 voxels in a 24^3 box, value 1 inside, falling to 0 over a voxel.
nodes::VolumeData::Ptr ball() {
    static const auto grid = [] {
        auto made =
            std::make_shared<volume::DenseScalarGrid>(volume::GridGeometry(glm::i64vec3(24)));
        for (int k = 0; k < 24; ++k)
            for (int j = 0; j < 24; ++j)
                for (int i = 0; i < 24; ++i) {
                    const float r = glm::length(glm::vec3(i, j, k) - 11.5f);
                    made->setValue({i, j, k}, glm::clamp(9.5f - r, 0.0f, 1.0f));
                }
        return made;
    }();
    auto volume = nodes::VolumeData::create();
    volume->setGrid(volume::ScalarGridPtr(grid));
    return volume;
}

struct BallScene {
    sg::Separator::Ptr root;
    nodes::TransferFunction::Ptr transfer;
    nodes::OrthographicCamera::Ptr camera;
};

BallScene ballScene(bool shade) {
    nodes::registerNodeTypes();
    BallScene scene;
    scene.camera = nodes::OrthographicCamera::create();
    scene.transfer = nodes::TransferFunction::create();
    scene.transfer->colorValues.setValue({0.0f, 1.0f});
    scene.transfer->colors.setValue({glm::vec3(1.0f, 0.8f, 0.6f), glm::vec3(1.0f, 0.8f, 0.6f)});
    scene.transfer->range = glm::vec2(0.0f, 1.0f);
    scene.transfer->opacities.setValue({0.0f, 3.0f});
    scene.transfer->unitDistance = 0.0f;
    scene.transfer->shade.setValue(shade);
    scene.root = sg::Separator::create();
    for (const sg::Node::Ptr& node :
         std::vector<sg::Node::Ptr>{scene.camera, scene.transfer, ball(),
                                    nodes::TextureSplat::create()}) {
        scene.root->addChild(node);
    }
    sg::BoundingBoxAction box;
    box.apply(*scene.root);
    scene.camera->viewAll(box.boundingBox(), 1.0f);
    return scene;
}

constexpr int kSize = 64;

image::Image splats(const BallScene& scene, render::FrameAction& action) {
    const render::cpu::CpuRenderer renderer(2);
    return renderer.draw(action.collect(*scene.root), action.statistics(), false);
}

image::Image reference(const BallScene& scene) {
    sg::RayCastAction action(kSize, kSize);
    action.render(*scene.root);
    return rayCastImage(action);
}

// Mean red over the disk of radius `r1` less that of radius `r0` about the image's centre.
double ringMean(const image::Image& image, double r0, double r1) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const double r = std::hypot(x + 0.5 - kSize / 2.0, y + 0.5 - kSize / 2.0);
            if (r >= r0 && r < r1) {
                sum += image.pixel(x, y).r;
                ++count;
            }
        }
    return sum / count;
}

TEST(ShadedVolume, aBallIsAFlatDiskUnshadedAndALitSphereShaded) {
    // The ball fills about 9.5 / (12 √3) of the view's half height: a disk of radius ~14 px.
    render::FrameAction flatAction(kSize, kSize);
    const image::Image flat = splats(ballScene(false), flatAction);
    render::FrameAction litAction(kSize, kSize);
    const BallScene shaded = ballScene(true);
    const image::Image lit = splats(shaded, litAction);
    const double flatCentre = ringMean(flat, 0.0, 4.0);
    const double flatRim = ringMean(flat, 10.0, 12.0);
    EXPECT_NEAR(flatRim / flatCentre, 1.0, 0.05) << "unshaded: the same colour to the rim";
    const double litCentre = ringMean(lit, 0.0, 4.0);
    const double litRim = ringMean(lit, 10.0, 12.0);
    // The headlight: a full diffuse and highlight where the sphere faces the eye, less towards
    // the rim, where the surface turns away.
    EXPECT_GT(litCentre, 0.85) << "0.1 + 0.7 + the highlight";
    EXPECT_LT(litRim / litCentre, 0.8) << "the rim turns away from the light";
    // The reference lights each sample by the gradient interpolated there, the splats each
    // voxel by its own: a voxel just inside the surface has none (only the ambient part), so
    // the splats' sphere is a little darker.
    const image::Image exact = reference(shaded);
    EXPECT_NEAR(ringMean(exact, 0.0, 4.0), litCentre, 0.07);
    EXPECT_NEAR(ringMean(exact, 10.0, 12.0), litRim, 0.07);
    const double psnr = image::ImageComparison(exact, lit).rgb().psnr;
    std::cout << "shaded ball, splats against the reference: " << psnr << " dB\n";
    EXPECT_GT(psnr, 25.0);
}

TEST(ShadedVolume, isLitAgainOnlyWhenTheLightOnItChanges) {
    const BallScene scene = ballScene(true);
    render::FrameAction action(kSize, kSize);
    splats(scene, action);
    EXPECT_EQ(action.statistics().builds.classifications, 1u);
    const image::Image first = splats(scene, action);
    EXPECT_EQ(action.statistics().builds.classifications, 0u);
    // A new title changes nothing drawn.
    scene.transfer->title.setValue("Density");
    EXPECT_EQ(image::ImageComparison(first, splats(scene, action)).rgb().rmse, 0.0);
    // Lighting fields light it again without classifying it again.
    scene.transfer->diffuse.setValue(0.2f);
    const image::Image dimmer = splats(scene, action);
    EXPECT_EQ(action.statistics().builds.classifications, 0u);
    EXPECT_LT(ringMean(dimmer, 0.0, 4.0), ringMean(first, 0.0, 4.0) - 0.3);
    // Off: the flat disk again.
    scene.transfer->shade.setValue(false);
    render::FrameAction flatAction(kSize, kSize);
    const image::Image off = splats(scene, action);
    EXPECT_EQ(image::ImageComparison(off, splats(ballScene(false), flatAction)).rgb().rmse, 0.0);
}

TEST(ShadedVolume, aLightOfTheSceneLightsTheSideItShinesOn) {
    BallScene scene = ballScene(true);
    auto light = nodes::DirectionalLight::create();
    light->direction.setValue(glm::vec3(-1.0f, 0.0f, 0.0f)); // from +x: the right side
    scene.root->insertChild(light, 1);
    scene.transfer->specular.setValue(0.0f);
    render::FrameAction action(kSize, kSize);
    const image::Image lit = splats(scene, action);
    // The rim at the right (+x in the image) faces the light, the centre does not.
    double right = 0.0;
    double centre = 0.0;
    for (int y = 28; y < 36; ++y) {
        right += lit.pixel(kSize / 2 + 12, y).r;
        centre += lit.pixel(kSize / 2, y).r;
    }
    EXPECT_GT(right, 2.0 * centre);
}

} // namespace
} // namespace texsplat::render
