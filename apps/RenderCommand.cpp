#include "apps/Commands.h"

#include "nodes/Camera.h"
#include "nodes/DefaultScene.h"
#include "nodes/NodeTypes.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/image/ImageIo.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/RayCastImage.h"
#include "nodes/render/RenderedImage.h"
#include "scenegraph/Error.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/RayCastAction.h"
#include "scenegraph/actions/RenderAction.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/gl/EglContext.h"
#include "scenegraph/io/SceneReader.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include <unistd.h>

namespace texsplat::apps {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The default scene is seen from the side, its funnel (the tornado's z axis) upright.
const glm::vec3 kDefaultSceneDirection(0.0f, 1.0f, -0.25f);

struct RenderArguments {
    std::string scene;
    std::string output;
    std::string size = "512x512";
    std::string camera;
    std::string direction;
    bool timeReport = false;
    bool rayCast = false;
    float rayCastStep = sg::RayCastAction::kDefaultStepSize;
};

// "WxH" with whole numbers from 1 to 16384 (beyond any GL framebuffer limit we could meet).
glm::ivec2 parseSize(const std::string& text) {
    const std::size_t x = text.find('x');
    const auto whole = [](const std::string& part, int& value) {
        if (part.empty() || part.size() > 5 ||
            !std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; })) {
            return false;
        }
        value = std::stoi(part);
        return value >= 1 && value <= 16384;
    };
    glm::ivec2 size(0);
    if (x == std::string::npos || !whole(text.substr(0, x), size.x) ||
        !whole(text.substr(x + 1), size.y)) {
        throw DataError("--size: expected WxH with whole numbers from 1 to 16384, got '" + text +
                        "'");
    }
    return size;
}

// "x,y,z", finite and not zero.
glm::vec3 parseDirection(const std::string& text) {
    std::istringstream stream(text);
    glm::vec3 direction(0.0f);
    char comma1 = 0;
    char comma2 = 0;
    stream >> direction.x >> comma1 >> direction.y >> comma2 >> direction.z;
    const bool finite = std::isfinite(direction.x) && std::isfinite(direction.y) &&
                        std::isfinite(direction.z);
    if (!stream || comma1 != ',' || comma2 != ',' || !(stream >> std::ws).eof() || !finite ||
        direction == glm::vec3(0.0f)) {
        throw DataError("--direction: expected three numbers x,y,z not all zero, got '" + text +
                        "'");
    }
    return direction;
}

const nodes::Camera* findCamera(sg::Node& scene) {
    sg::SearchAction search;
    search.setType(nodes::Camera::classType());
    search.setInterest(sg::SearchAction::Interest::First);
    search.apply(scene);
    return search.paths().empty() ? nullptr
                                  : static_cast<const nodes::Camera*>(search.paths().front().tail().get());
}

// The scene as drawn: as it is when it has a camera, else under a camera that frames it.
sg::Node::Ptr withCamera(const sg::Node::Ptr& scene, const RenderArguments& arguments,
                         float aspect) {
    if (const nodes::Camera* camera = findCamera(*scene)) {
        if (!arguments.camera.empty() || !arguments.direction.empty()) {
            throw DataError("--direction/--camera: the scene has its own camera (" +
                            camera->describe() + "); they frame scenes without one");
        }
        return scene;
    }
    nodes::Camera::Ptr camera;
    if (arguments.camera.empty() || arguments.camera == "perspective") {
        camera = nodes::PerspectiveCamera::create();
    } else if (arguments.camera == "orthographic") {
        camera = nodes::OrthographicCamera::create();
    } else {
        throw DataError("--camera: expected 'perspective' or 'orthographic', got '" +
                        arguments.camera + "'");
    }
    const glm::vec3 direction = !arguments.direction.empty() ? parseDirection(arguments.direction)
                                : arguments.scene.empty()    ? kDefaultSceneDirection
                                                             : glm::vec3(0.0f, 0.0f, -1.0f);
    camera->orientation.setValue(render::rotationLookingAlong(direction));
    sg::BoundingBoxAction box;
    box.apply(*scene);
    if (box.boundingBox().isEmpty()) {
        throw DataError((arguments.scene.empty() ? std::string("default scene") : arguments.scene) +
                        ": nothing to frame (the scene has no geometry and no camera)");
    }
    camera->viewAll(box.boundingBox(), aspect);
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(camera);
    root->addChild(scene);
    return root;
}

void printTimes(const sg::RenderStatistics& statistics, double readScene, double context,
                const gl::ContextInfo& contextInfo, double write) {
    std::printf("time report (wall seconds):\n");
    std::printf("  %-10s %9.4f  (scene file)\n", "read", readScene);
    std::printf("  %-10s %9.4f  (%s: %s)\n", "context", context, contextInfo.platform.c_str(),
                contextInfo.summary().c_str());
    for (std::size_t phase = 0; phase < sg::kRenderPhaseCount; ++phase) {
        const auto name = std::string(sg::toString(static_cast<sg::RenderPhase>(phase)));
        std::printf("  %-10s %9.4f\n", name.c_str(), statistics.seconds[phase]);
    }
    std::printf("  %-10s %9.4f  (encode and rename)\n", "write", write);
    std::printf("  splats %zu, triangles %zu\n", statistics.splats, statistics.triangles);
}

// Progress of a ray cast on stderr: one updating line on a terminal; otherwise, once the render
// has run for a few seconds, a line every 10% (batch logs stay short for small images).
class RayCastProgress {
public:
    RayCastProgress() : mTerminal(isatty(STDERR_FILENO) == 1), mStart(Clock::now()) {}

    bool operator()(double fraction) {
        const int percent = static_cast<int>(fraction * 100.0);
        if (mTerminal) {
            if (percent != mLastPercent) {
                std::fprintf(stderr, "\rray casting: %3d%%%s", percent, fraction >= 1.0 ? "\n" : "");
            }
        } else if (secondsSince(mStart) > 2.0 && percent / 10 != mLastPercent / 10) {
            std::fprintf(stderr, "ray casting: %d%%\n", percent / 10 * 10);
        }
        mLastPercent = percent;
        return true;
    }

private:
    bool mTerminal;
    Clock::time_point mStart;
    int mLastPercent = -1;
};

// The reference image of --raycast: no GL context; the same camera, size and background as
// the GL render, so the two images compare pixel by pixel.
void runRayCast(const RenderArguments& arguments, sg::Node& root, glm::ivec2 size,
                image::ImageFormat format, double readScene) {
    sg::RayCastAction action(size.x, size.y);
    action.setBackground(format == image::ImageFormat::Png ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)
                                                           : glm::vec4(0.0f));
    action.setStepSize(arguments.rayCastStep);
    action.setProgress(RayCastProgress());
    Clock::time_point start = Clock::now();
    action.render(root);
    const double integrate = secondsSince(start);
    const image::Image image = render::rayCastImage(action);
    start = Clock::now();
    image::writeImage(image, arguments.output);
    const double write = secondsSince(start);
    if (arguments.timeReport) {
        std::printf("time report (wall seconds):\n");
        std::printf("  %-10s %9.4f  (scene file)\n", "read", readScene);
        std::printf("  %-10s %9.4f  (load, classify, integrate: ray cast, %u threads)\n",
                    "ray cast", integrate, std::max(1u, std::thread::hardware_concurrency()));
        std::printf("  %-10s %9.4f  (encode and rename)\n", "write", write);
    }
}

void runRender(const RenderArguments& arguments) {
    const glm::ivec2 size = parseSize(arguments.size);
    // Refuse a bad output name before any work, so nothing is left half-done.
    const image::ImageFormat format = image::imageFormatOf(arguments.output);
    if (format == image::ImageFormat::Exr && !image::isExrSupported()) {
        throw IoError(arguments.output + ": this build has no OpenEXR support");
    }
    nodes::registerNodeTypes();
    sg::registerEngineTypes(sg::NodeRegistry::instance());

    Clock::time_point start = Clock::now();
    const sg::Node::Ptr scene = arguments.scene.empty()
                                    ? sg::Node::Ptr(nodes::makeDefaultScene())
                                    : sg::SceneReader::readFile(arguments.scene);
    const double readScene = secondsSince(start);
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    const sg::Node::Ptr root = withCamera(scene, arguments, aspect);

    if (!arguments.rayCast && arguments.rayCastStep != sg::RayCastAction::kDefaultStepSize) {
        throw DataError("--raycast-step: only with --raycast");
    }
    if (arguments.rayCast) {
        runRayCast(arguments, *root, size, format, readScene);
        return;
    }
    start = Clock::now();
    gl::EglContext context;
    const double contextTime = secondsSince(start);
    sg::RenderAction action(size.x, size.y);
    // PNG stores straight alpha, which cannot hold light from a transparent medium (alpha 0,
    // color > 0): composite over opaque black. EXR keeps the premultiplied layer with its alpha.
    action.setBackground(format == image::ImageFormat::Png ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)
                                                           : glm::vec4(0.0f));
    action.render(*root);
    const image::Image image = render::renderedImage(
        action, format == image::ImageFormat::Exr ? render::DepthReadback::With
                                                  : render::DepthReadback::Without);
    start = Clock::now();
    image::writeImage(image, arguments.output);
    const double write = secondsSince(start);
    if (arguments.timeReport) {
        printTimes(action.statistics(), readScene, contextTime, context.info(), write);
    }
}

} // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto arguments = std::make_shared<RenderArguments>();
    CLI::App* command = app.add_subcommand(
        "render", "Render a scene file (or the built-in tornado scene) to a PNG or OpenEXR image, "
                  "headless");
    command->add_option("scene", arguments->scene,
                        "Inventor scene file (.iv); none: the built-in tornado with fibers");
    command->add_option("-o,--output", arguments->output, "Output image: .png or .exr (float RGBA, Z)")
        ->required();
    command->add_option("--size", arguments->size, "Image size WxH")->capture_default_str();
    command->add_option("--camera", arguments->camera,
                        "perspective|orthographic: the camera that frames a scene without one "
                        "(default perspective)");
    command->add_option("--direction", arguments->direction,
                        "x,y,z: viewing direction of that camera");
    command->add_flag("--time-report", arguments->timeReport,
                      "Print where the time went (read, context, load, classify, order, upload, "
                      "draw, read back, write)");
    command->add_flag("--raycast", arguments->rayCast,
                      "Render the reference with the CPU ray caster (exact emission-absorption of "
                      "the same reconstructed field, no GL context; progress on stderr)");
    command->add_option("--raycast-step", arguments->rayCastStep,
                        "Integration step of --raycast in voxels")
        ->capture_default_str();
    command->callback([arguments, &exitCode] {
        runRender(*arguments);
        exitCode = kExitOk;
    });
}

} // namespace texsplat::apps
