// Rendering a scene file's graph as `texsplat render` does (SceneRenderer, viewedScene()), which
// the command line and the Python module share so that they give the same image.
#include "nodes/render/SceneRenderer.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/SceneImage.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/WorkProgress.h"
#include "tests/scenegraph/ScopedMemoryLimit.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace texsplat::render {
namespace {

using nodes::test::errorOf;

sg::Separator::Ptr blobScene() {
    nodes::registerNodeTypes();
    auto data = nodes::VolumeData::create();
    data->resolution.setValue(glm::vec3(16.0f));
    auto scene = sg::Separator::create();
    scene->addChild(data);
    scene->addChild(nodes::TransferFunction::create());
    scene->addChild(nodes::TextureSplat::create());
    return scene;
}

SceneRenderOptions cpuOptions(int width, int height) {
    SceneRenderOptions options;
    options.width = width;
    options.height = height;
    options.backend = BackendRequest::Cpu;
    return options;
}

TEST(SceneRenderer, drawsWhatSceneImageDraws) {
    const sg::Separator::Ptr scene = blobScene();
    SceneRenderer renderer(cpuOptions(40, 30));
    const image::Image image = renderer.render(*framedScene(scene, 40.0f / 30.0f));
    SceneImageOptions reference;
    reference.width = 40;
    reference.height = 30;
    const image::Image expected = sceneImage(scene, reference);
    EXPECT_EQ(image.pixels(), expected.pixels());
    EXPECT_GT(renderer.statistics().splats, 0u);
    EXPECT_EQ(renderer.description().rfind("CPU (", 0), 0u) << renderer.description();
    EXPECT_EQ(renderer.stage(), "rendering a 40x30 image");
}

TEST(SceneRenderer, refusesABadSizeAndAnImageBeyondTheMemoryLimit) {
    EXPECT_EQ(errorOf<DataError>([] { SceneRenderer renderer(cpuOptions(0, 30)); }),
              "size: expected whole numbers from 1 to 16384, got 0x30");
    // Asked before the frame, after the scene's volumes (loaded here by framing) asked for theirs.
    const sg::Node::Ptr root = framedScene(blobScene(), 1.0f);
    SceneRenderOptions options = cpuOptions(64, 64);
    options.advice = "render less";
    SceneRenderer renderer(options);
    const test::ScopedMemoryLimit limit(1024);
    EXPECT_EQ(errorOf<ResourceError>([&] { renderer.render(*root); }),
              "rendering a 64x64 image would need 65536 bytes (64 KiB), more than the memory "
              "limit of 1024 bytes (1 KiB); render less");
}

TEST(SceneRenderer, reportsTheDrawToItsWorkProgressWhichMayCancel) {
    SceneRenderer renderer(cpuOptions(16, 16));
    std::vector<std::pair<std::string, double>> reports;
    renderer.setWorkProgress([&](std::string_view step, double fraction) {
        reports.emplace_back(std::string(step), fraction);
        return true;
    });
    const sg::Node::Ptr root = framedScene(blobScene(), 1.0f);
    renderer.render(*root);
    ASSERT_GE(reports.size(), 2u);
    EXPECT_EQ(reports[reports.size() - 2], std::make_pair(std::string("drawing"), 0.0));
    EXPECT_EQ(reports.back(), std::make_pair(std::string("drawing"), 1.0));
    // Cancelled before the draw, at the latest.
    renderer.setWorkProgress([](std::string_view step, double) { return step != "drawing"; });
    EXPECT_THROW(renderer.render(*root), sg::Cancelled);
    renderer.setWorkProgress([](std::string_view, double) { return false; });
    EXPECT_THROW(renderer.render(*framedScene(blobScene(), 1.0f)), sg::Cancelled);
}

TEST(SceneFraming, viewedSceneTurnsTheScenesOwnCameraOrFramesOne) {
    const sg::Separator::Ptr scene = blobScene();
    ViewChange change;
    change.azimuth = 90.0f;
    change.zoom = 2.0f;
    const sg::Node::Ptr framed = viewedScene(scene, 1.0f, Framing{}, change);
    ASSERT_NE(framed, scene);
    auto* camera = dynamic_cast<nodes::PerspectiveCamera*>(findCamera(*framed));
    ASSERT_NE(camera, nullptr);
    // Turned a quarter about the up axis: looking along -x (or +x) instead of -z.
    const glm::vec3 view = camera->orientation.value().quaternion() * glm::vec3(0, 0, -1);
    EXPECT_NEAR(std::abs(view.x), 1.0f, 1e-5f);
    const float framedAngle = nodes::PerspectiveCamera::create()->heightAngle.value();
    EXPECT_LT(camera->heightAngle.value(), framedAngle);

    scene->insertChild(nodes::PerspectiveCamera::create(), 0);
    change = ViewChange{};
    change.direction = glm::vec3(1, 0, 0);
    EXPECT_EQ(viewedScene(scene, 1.0f, Framing{}, change), scene);
    const glm::vec3 turned =
        findCamera(*scene)->orientation.value().quaternion() * glm::vec3(0, 0, -1);
    EXPECT_NEAR(turned.x, 1.0f, 1e-5f);
}

TEST(SceneFraming, refusesAViewChangeItCannotMake) {
    const sg::Separator::Ptr scene = blobScene();
    ViewChange change;
    change.zoom = 0.0f;
    EXPECT_EQ(errorOf<DataError>([&] { viewedScene(scene, 1.0f, Framing{}, change); }),
              "zoom: expected a magnification > 0, got 0");
    change = ViewChange{};
    change.direction = glm::vec3(0.0f);
    EXPECT_EQ(errorOf<DataError>([&] { viewedScene(scene, 1.0f, Framing{}, change); }),
              "direction: expected three finite numbers x,y,z not all zero, got 0,0,0");
}

} // namespace
} // namespace texsplat::render
