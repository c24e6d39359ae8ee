#include "nodes/TextureSplat.h"

#include "SplatTestSupport.h"
#include "nodes/GaussianSplat.h"
#include "nodes/Coordinate3.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/Material.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/CameraView.h"
#include "nodes/volume/DenseGrid.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

namespace texsplat::nodes {
namespace {

// Voxel values of the test volumes, classified by threeClasses(): 0 empty, 1 an opaque red
// medium (τ = 50 per voxel), 2 a transparent medium glowing green (emission 1 per voxel).
constexpr float kEmpty = 0.0f;
constexpr float kOpaqueRed = 1.0f;
constexpr float kGlowingGreen = 2.0f;

TransferFunction::Ptr threeClasses() {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 2.0f));
    transfer->colorValues.setValue({0.0f, 0.5f, 1.0f});
    transfer->colors.setValue({glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f),
                               glm::vec3(0.0f, 1.0f, 0.0f)});
    transfer->opacityValues.setValue({0.0f, 0.5f, 1.0f});
    transfer->opacities.setValue({0.0f, 50.0f, 0.0f});
    transfer->emission.setValue(1.0f);
    return transfer;
}

// A cube of `size` voxels: an opaque shell `shell` voxels thick around a glowing interior.
std::string shellVolume(int size, int shell) {
    volume::DenseGrid<float> grid{volume::GridGeometry(glm::i64vec3(size))};
    for (int k = 0; k < size; ++k) {
        for (int j = 0; j < size; ++j) {
            for (int i = 0; i < size; ++i) {
                const int inset = std::min({i, j, k, size - 1 - i, size - 1 - j, size - 1 - k});
                grid.setValue({i, j, k}, inset < shell ? kOpaqueRed : kGlowingGreen);
            }
        }
    }
    return test::writeTestVolume(
        "shell" + std::to_string(size) + "_" + std::to_string(shell), grid);
}

// camera, transfer function, volume, then `extra` nodes.
sg::Separator::Ptr volumeScene(const Camera::Ptr& camera, const std::string& path,
                               const std::vector<sg::Node::Ptr>& extra) {
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(camera);
    root->addChild(threeClasses());
    root->addChild(test::fileVolume(VolumeSource::FileRaw, path));
    for (const sg::Node::Ptr& node : extra) {
        root->addChild(node);
    }
    return root;
}

// Largest green and red over the image.
glm::vec2 maxGreenRed(const image::Image& image) {
    const image::Image::Statistics statistics = image.statistics();
    return {static_cast<float>(statistics.maximum.g), static_cast<float>(statistics.maximum.r)};
}

TEST(TextureSplat, opaqueShellHidesTheGlowingInteriorFromAxisAndObliqueViews) {
    test::sharedContext();
    const std::string path = shellVolume(10, 2);
    const std::vector<glm::vec3> axes{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& axis : axes) {
        OrthographicCamera::Ptr camera = OrthographicCamera::create();
        camera->orientation.setValue(render::rotationLookingAlong(axis));
        sg::Separator::Ptr root = volumeScene(camera, path, {TextureSplat::create()});
        test::frameCamera(*camera, *root);
        const glm::vec2 greenRed = maxGreenRed(test::renderScene(*root, 48, 48));
        EXPECT_LT(greenRed.x, 1e-3f) << "axis view " << axis.x << " " << axis.y << " " << axis.z;
        EXPECT_GT(greenRed.y, 0.9f);
    }
    for (const glm::vec3& direction : {glm::vec3(-1.0f, -0.7f, -0.4f), glm::vec3(0.5f, -1.0f, 0.8f)}) {
        PerspectiveCamera::Ptr camera = PerspectiveCamera::create();
        camera->orientation.setValue(render::rotationLookingAlong(direction));
        sg::Separator::Ptr root = volumeScene(camera, path, {TextureSplat::create()});
        test::frameCamera(*camera, *root);
        const glm::vec2 greenRed = maxGreenRed(test::renderScene(*root, 48, 48));
        EXPECT_LT(greenRed.x, 1e-3f) << "oblique view " << direction.x << " " << direction.y;
        EXPECT_GT(greenRed.y, 0.9f);
    }
}

TEST(TextureSplat, withoutTheShellTheInteriorGlows) {
    test::sharedContext();
    const std::string path = shellVolume(10, 0);
    OrthographicCamera::Ptr camera = OrthographicCamera::create();
    sg::Separator::Ptr root = volumeScene(camera, path, {TextureSplat::create()});
    test::frameCamera(*camera, *root);
    const glm::vec2 greenRed = maxGreenRed(test::renderScene(*root, 48, 48));
    // Ten voxels of emission 1 per unit length along z.
    EXPECT_NEAR(greenRed.x, 10.0f, 0.1f);
    EXPECT_EQ(greenRed.y, 0.0f);
}

// A slab of glowing voxels cut in half by an opaque red square at z = 3.5, covering x < 3.5.
TEST(TextureSplat, splatsBehindAnOpaqueMeshAreHiddenAndInFrontBlendOverIt) {
    test::sharedContext();
    const std::string path = shellVolume(8, 0);
    OrthographicCamera::Ptr camera = OrthographicCamera::create();
    Coordinate3::Ptr corners = Coordinate3::create();
    corners->point.setValue({glm::vec3(-4.0f, -4.0f, 3.5f), glm::vec3(3.5f, -4.0f, 3.5f),
                             glm::vec3(3.5f, 12.0f, 3.5f), glm::vec3(-4.0f, 12.0f, 3.5f)});
    IndexedFaceSet::Ptr square = IndexedFaceSet::create();
    square->coordIndex.setValue({0, 1, 2, 3, -1});
    Material::Ptr red = Material::create();
    red->diffuseColor.setValue({glm::vec3(0.0f)});
    red->emissiveColor.setValue({glm::vec3(1.0f, 0.0f, 0.0f)});
    sg::Separator::Ptr root =
        volumeScene(camera, path, {red, corners, square, TextureSplat::create()});
    test::frameCamera(*camera, *root);
    const image::Image image = test::renderScene(*root, 64, 64);
    // The view frames the square and the volume (x from -4 to 7.5): the volume covers about
    // columns 22 to 50, the square's edge x = 3.5 is column 38.
    const auto mean = [&image](int x0, int x1) {
        glm::dvec4 sum(0.0);
        for (int y = 28; y < 36; ++y) {
            for (int x = x0; x < x1; ++x) {
                sum += glm::dvec4(image.pixel(x, y));
            }
        }
        return sum / double((x1 - x0) * 8);
    };
    const glm::dvec4 covered = mean(28, 36);
    const glm::dvec4 open = mean(40, 46);
    EXPECT_NEAR(open.g, 8.0, 0.1);   // all eight layers
    EXPECT_EQ(open.r, 0.0);
    EXPECT_NEAR(covered.r, 1.0, 1e-6); // the square, seen through transparent splats
    EXPECT_NEAR(covered.g, 4.0, 0.3);  // only the four layers in front of it
    EXPECT_NEAR(covered.a, 1.0, 1e-6);
}

// Camera extremes: images stay finite and show something.
TEST(TextureSplat, cameraInsideAtTheNearPlaneFarAwayAndCloseGivesFiniteImages) {
    test::sharedContext();
    const std::string path = shellVolume(10, 2);
    const auto render = [&path](const glm::vec3& position, const glm::vec3& direction,
                                float nearDistance, float farDistance) {
        PerspectiveCamera::Ptr camera = PerspectiveCamera::create();
        camera->position.setValue(position);
        camera->orientation.setValue(render::rotationLookingAlong(direction));
        camera->nearDistance.setValue(nearDistance);
        camera->farDistance.setValue(farDistance);
        sg::Separator::Ptr root = volumeScene(camera, path, {TextureSplat::create()});
        return test::renderScene(*root, 33, 33);
    };
    test::expectFiniteAndNotEmpty(render({4.5f, 4.5f, 4.5f}, {0.3f, 0.2f, -1.0f}, 0.01f, 100.0f),
                                  "eye inside the volume");
    test::expectFiniteAndNotEmpty(render({4.5f, 4.5f, 9.5f}, {0.0f, 0.0f, -1.0f}, 5.0f, 100.0f),
                                  "near plane through the volume's middle");
    test::expectFiniteAndNotEmpty(render({4.5f, 4.5f, 300.0f}, {0.0f, 0.0f, -1.0f}, 1.0f, 1000.0f),
                                  "far away: sub-pixel splats");
    // 0.3 voxels in front of a corner voxel: its square alone covers the view.
    const image::Image close = render({-0.3f, -0.3f, -0.3f}, {1.0f, 1.0f, 1.0f}, 0.001f, 100.0f);
    test::expectFiniteAndNotEmpty(close, "close: one splat covers the screen");
    EXPECT_GT(close.statistics().minimum.r, 0.0);
}

// With the eye inside the volume, only the voxels in front of the eye plane make splats: the
// count is exactly the number of voxel centres c with (c − eye)·d > 0, fewer than from outside.
TEST(TextureSplat, eyeInsideTheVolumeCullsTheSplatsBehindIt) {
    test::sharedContext();
    constexpr int kSize = 10;
    const std::string path = shellVolume(kSize, 2);
    const auto splatsDrawn = [&path](const glm::vec3& position, const glm::vec3& direction) {
        PerspectiveCamera::Ptr camera = PerspectiveCamera::create();
        camera->position.setValue(position);
        camera->orientation.setValue(render::rotationLookingAlong(direction));
        camera->nearDistance.setValue(0.01f);
        camera->farDistance.setValue(100.0f);
        sg::Separator::Ptr root = volumeScene(camera, path, {TextureSplat::create()});
        const test::RenderedFrame frame = test::renderFrame(*root, 33, 33);
        test::expectFiniteAndNotEmpty(frame.image, "camera at " + std::to_string(position.z));
        return frame.statistics.splats;
    };
    const glm::vec3 direction(0.3f, 0.2f, -1.0f);
    const glm::vec3 inside(4.5f, 4.5f, 4.5f);
    std::size_t inFront = 0;
    for (int k = 0; k < kSize; ++k) {
        for (int j = 0; j < kSize; ++j) {
            for (int i = 0; i < kSize; ++i) {
                // No voxel centre lies on this eye plane (0.3a + 0.2b − c = 0 has no solution in
                // half-odd a, b, c), so float rounding cannot flip one.
                inFront += glm::dot(glm::vec3(i, j, k) - inside, direction) > 0.0f ? 1 : 0;
            }
        }
    }
    const std::size_t outsideCount = splatsDrawn(inside - 30.0f * direction, direction);
    const std::size_t insideCount = splatsDrawn(inside, direction);
    EXPECT_EQ(outsideCount, static_cast<std::size_t>(kSize * kSize * kSize));
    EXPECT_EQ(insideCount, inFront);
    EXPECT_LT(insideCount, outsideCount);
    RecordProperty("splats_outside", std::to_string(outsideCount));
    RecordProperty("splats_inside", std::to_string(insideCount));
}

// The paper's figure 2 through the scene nodes: a raw file of one 16 x 16 layer of value 1,
// classified to emission 1 and no opacity, drawn by TextureSplat (paper kernel, default 64²
// texture) through an orthographic camera looking down z into the float framebuffer.
TEST(TextureSplat, figure2LayerThroughTheNodesIsAsFlatAsThePaperReports) {
    test::sharedContext();
    const sg::Separator::Ptr root = test::figure2LayerScene("figure2_layer");
    const test::RenderedFrame frame =
        test::renderFrame(*root, test::kLayerImageSize, test::kLayerImageSize);
    EXPECT_EQ(frame.statistics.splats,
              static_cast<std::size_t>(test::kLayerVoxels * test::kLayerVoxels));
    EXPECT_EQ(frame.image.statistics().maximum.a, 0.0) << "transparent splats must leave alpha 0";
    const test::LayerStatistics statistics = test::redLayerStatistics(frame.image);
    test::reportLayer("scene nodes: raw file, TransferFunction, TextureSplat", statistics);
    EXPECT_NEAR(statistics.mean, 1.0, 2e-3);
    EXPECT_NEAR(statistics.relativeMax(), test::kPaperLayerMax, 1e-3 * test::kPaperLayerMax);
    EXPECT_NEAR(statistics.relativeMin(), test::kPaperLayerMin, 1e-3 * test::kPaperLayerMin);
}

TEST(TextureSplat, reportsMissingStateAndBadFields) {
    test::sharedContext();
    nodes::registerNodeTypes();
    const auto message = [](sg::Node& root) {
        try {
            test::renderScene(root, 8, 8);
        } catch (const DataError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    TextureSplat::Ptr splat = TextureSplat::create();
    splat->setName("s");
    sg::Separator::Ptr noCamera = sg::Separator::create();
    noCamera->addChild(threeClasses());
    noCamera->addChild(test::fileVolume(VolumeSource::FileRaw, shellVolume(4, 0)));
    noCamera->addChild(splat);
    EXPECT_EQ(message(*noCamera), "TextureSplat 's': no camera before this node");
    sg::Separator::Ptr noVolume = sg::Separator::create();
    noVolume->addChild(OrthographicCamera::create());
    noVolume->addChild(splat);
    EXPECT_EQ(message(*noVolume), "TextureSplat 's': no VolumeData before this node");
    sg::Separator::Ptr noTransfer = sg::Separator::create();
    noTransfer->addChild(OrthographicCamera::create());
    noTransfer->addChild(test::fileVolume(VolumeSource::FileRaw, shellVolume(4, 0)));
    noTransfer->addChild(splat);
    EXPECT_EQ(message(*noTransfer), "TextureSplat 's': no TransferFunction before this node");
    splat->size.setValue(-1.0f);
    EXPECT_EQ(message(*noTransfer), "TextureSplat 's': size must be finite and > 0, got -1");
}

}  // namespace
}  // namespace texsplat::nodes
