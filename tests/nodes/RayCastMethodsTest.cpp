#include "nodes/render/RayCastMethods.h"

#include "SceneNodesTestSupport.h"
#include "nodes/Coordinate3.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/Material.h"
#include "nodes/NodeTypes.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/RayCastImage.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/RawVolume.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/RayCastAction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

// 0 empty, 1 glowing green (emission 1 per unit length, no absorption), 2 opaque red (τ = 50).
TransferFunction::Ptr glowAndWall() {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 2.0f));
    transfer->colorValues.setValue({0.0f, 0.5f, 1.0f});
    transfer->colors.setValue({glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                               glm::vec3(1.0f, 0.0f, 0.0f)});
    transfer->opacityValues.setValue({0.0f, 0.5f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.0f, 50.0f});
    transfer->emission.setValue(1.0f);
    return transfer;
}

VolumeData::Ptr cube(const std::string& name, int size, float value) {
    volume::DenseGrid<float> grid{volume::GridGeometry(glm::i64vec3(size))};
    for (int k = 0; k < size; ++k) {
        for (int j = 0; j < size; ++j) {
            for (int i = 0; i < size; ++i) {
                grid.setValue({i, j, k}, value);
            }
        }
    }
    const std::string path = test::testPath(name + ".raw");
    volume::writeRawVolume(path, grid);
    VolumeData::Ptr volume = VolumeData::create();
    volume->source.setValue(VolumeSource::FileRaw);
    volume->fileName.setValue(path);
    return volume;
}

image::Image rayCast(sg::Node& root, int width, int height) {
    registerNodeTypes();
    sg::RayCastAction action(width, height);
    action.setThreadCount(2);
    action.render(root);
    return render::rayCastImage(action);
}

void frame(Camera& camera, sg::Node& root) {
    sg::BoundingBoxAction box;
    box.apply(root);
    camera.viewAll(box.boundingBox(), 1.0f);
}

glm::dvec4 mean(const image::Image& image, int x0, int x1, int y0, int y1) {
    glm::dvec4 sum(0.0);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            sum += glm::dvec4(image.pixel(x, y));
        }
    }
    return sum / double((x1 - x0) * (y1 - y0));
}

// A glowing 8³ cube cut in half by an opaque red square at z = 3.5 covering x < 3.5: the same
// scene as TextureSplat's occlusion test, with the same expectations.
TEST(RayCastMethods, anOpaqueMeshHidesTheVolumeBehindItAndShowsThroughTheFront) {
    OrthographicCamera::Ptr camera = OrthographicCamera::create();
    Coordinate3::Ptr corners = Coordinate3::create();
    corners->point.setValue({glm::vec3(-4.0f, -4.0f, 3.5f), glm::vec3(3.5f, -4.0f, 3.5f),
                             glm::vec3(3.5f, 12.0f, 3.5f), glm::vec3(-4.0f, 12.0f, 3.5f)});
    IndexedFaceSet::Ptr square = IndexedFaceSet::create();
    square->coordIndex.setValue({0, 1, 2, 3, -1});
    Material::Ptr red = Material::create();
    red->diffuseColor.setValue({glm::vec3(0.0f)});
    red->emissiveColor.setValue({glm::vec3(1.0f, 0.0f, 0.0f)});
    sg::Separator::Ptr root = sg::Separator::create();
    for (const sg::Node::Ptr& node : std::vector<sg::Node::Ptr>{
             camera, glowAndWall(), cube("glow8", 8, 1.0f), red, corners, square,
             TextureSplat::create()}) {
        root->addChild(node);
    }
    frame(*camera, *root);
    const image::Image image = rayCast(*root, 64, 64);
    const glm::dvec4 covered = mean(image, 28, 36, 28, 36);
    const glm::dvec4 open = mean(image, 40, 46, 28, 36);
    EXPECT_NEAR(open.g, 8.0, 0.05); // all eight layers (lattice sum 1 ± 0.005)
    EXPECT_EQ(open.r, 0.0);
    EXPECT_EQ(open.a, 0.0);
    EXPECT_NEAR(covered.r, 1.0, 1e-6); // the square's emissive red, unlit (diffuse black)
    EXPECT_NEAR(covered.g, 4.0, 0.05); // the four layers in front of it
    EXPECT_NEAR(covered.a, 1.0, 1e-6);
}

TEST(RayCastMethods, meshesAreLitLikeTheOpaquePass) {
    // A square facing +z under the default headlight (the view direction −z): |n·l| = 1, so the
    // pixel is the diffuse color; tilted by 60° about y, half of it.
    for (float angle : {0.0f, 60.0f}) {
        const float radians = angle * 3.14159265f / 180.0f;
        const glm::vec3 u(std::cos(radians), 0.0f, -std::sin(radians));
        Coordinate3::Ptr corners = Coordinate3::create();
        corners->point.setValue({-2.0f * u + glm::vec3(0, -2, 0), 2.0f * u + glm::vec3(0, -2, 0),
                                 2.0f * u + glm::vec3(0, 2, 0), -2.0f * u + glm::vec3(0, 2, 0)});
        IndexedFaceSet::Ptr square = IndexedFaceSet::create();
        square->coordIndex.setValue({0, 1, 2, 3, -1});
        Material::Ptr material = Material::create();
        material->diffuseColor.setValue({glm::vec3(0.2f, 0.4f, 0.8f)});
        OrthographicCamera::Ptr camera = OrthographicCamera::create();
        camera->position.setValue(glm::vec3(0.0f, 0.0f, 10.0f));
        camera->height.setValue(2.0f);
        camera->farDistance.setValue(20.0f);
        sg::Separator::Ptr root = sg::Separator::create();
        root->addChild(camera);
        root->addChild(material);
        root->addChild(corners);
        root->addChild(square);
        const glm::vec4 pixel = rayCast(*root, 4, 4).pixel(2, 2);
        const float lambert = std::cos(radians);
        EXPECT_NEAR(pixel.r, 0.2f * lambert, 1e-5f) << angle;
        EXPECT_NEAR(pixel.g, 0.4f * lambert, 1e-5f) << angle;
        EXPECT_NEAR(pixel.b, 0.8f * lambert, 1e-5f) << angle;
        EXPECT_EQ(pixel.a, 1.0f);
    }
}

TEST(RayCastMethods, nanAndInfiniteDataGiveAFiniteImage) {
    volume::DenseGrid<float> grid{volume::GridGeometry(glm::i64vec3(6))};
    const float specials[] = {std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(), 1e30f, -1e30f, 1.0f, 2.0f};
    int n = 0;
    for (int k = 0; k < 6; ++k) {
        for (int j = 0; j < 6; ++j) {
            for (int i = 0; i < 6; ++i) {
                grid.setValue({i, j, k}, specials[n++ % 7]);
            }
        }
    }
    const std::string path = test::testPath("specials.raw");
    volume::writeRawVolume(path, grid);
    VolumeData::Ptr volume = VolumeData::create();
    volume->source.setValue(VolumeSource::FileRaw);
    volume->fileName.setValue(path);
    for (bool perspective : {false, true}) {
        Camera::Ptr camera;
        if (perspective) {
            camera = PerspectiveCamera::create();
        } else {
            camera = OrthographicCamera::create();
        }
        camera->orientation.setValue(render::rotationLookingAlong(glm::vec3(-1.0f, -0.6f, -0.3f)));
        sg::Separator::Ptr root = sg::Separator::create();
        root->addChild(camera);
        root->addChild(glowAndWall());
        root->addChild(volume);
        root->addChild(TextureSplat::create());
        frame(*camera, *root);
        const image::Image::Statistics statistics = rayCast(*root, 16, 16).statistics();
        EXPECT_EQ(statistics.nonFinitePixels, 0u);
        EXPECT_GT(statistics.maximum.r + statistics.maximum.g, 0.0);
    }
}

TEST(RayCastMethods, reportsAMissingCameraOrVolumeLikeTheFrameAction) {
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(glowAndWall());
    root->addChild(cube("missing", 2, 1.0f));
    TextureSplat::Ptr splat = TextureSplat::create();
    root->addChild(splat);
    EXPECT_EQ(test::errorOf<DataError>([&] { rayCast(*root, 2, 2); }),
              "TextureSplat: no camera before this node");
    sg::Separator::Ptr noVolume = sg::Separator::create();
    noVolume->addChild(OrthographicCamera::create());
    noVolume->addChild(glowAndWall());
    noVolume->addChild(TextureSplat::create());
    EXPECT_EQ(test::errorOf<DataError>([&] { rayCast(*noVolume, 2, 2); }),
              "TextureSplat: no VolumeData before this node");
}

} // namespace
} // namespace texsplat::nodes
