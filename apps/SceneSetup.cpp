#include "apps/SceneSetup.h"

#include "nodes/Camera.h"
#include "nodes/DefaultScene.h"
#include "nodes/NodeTypes.h"
#include "nodes/ScalarSplat.h"
#include "nodes/render/SceneFraming.h"
#include "scenegraph/Error.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/io/SceneReader.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <sstream>

namespace texsplat::apps {
namespace {

// The default scene is seen from the side, its funnel (the tornado's z axis) upright.
const glm::vec3 kDefaultSceneDirection(0.0f, 1.0f, -0.25f);

// "a,b,c": three finite numbers separated by commas and nothing else, or nothing.
std::optional<glm::vec3> parseThreeNumbers(const std::string& text) {
    std::istringstream stream(text);
    glm::vec3 value(0.0f);
    char comma1 = 0;
    char comma2 = 0;
    stream >> value.x >> comma1 >> value.y >> comma2 >> value.z;
    const bool finite =
        std::isfinite(value.x) && std::isfinite(value.y) && std::isfinite(value.z);
    if (!stream || comma1 != ',' || comma2 != ',' || !(stream >> std::ws).eof() || !finite) {
        return std::nullopt;
    }
    return value;
}

// A finite number from an option's text, checked by `accept`; throws naming the option.
float parseNumber(const std::string& text, const char* option, const char* expected,
                  bool (*accept)(float)) {
    float value = 0.0f;
    const char* end = text.data() + text.size();
    const auto [parsed, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || parsed != end || !std::isfinite(value) ||
        !accept(value)) {
        throw DataError(std::string(option) + ": expected " + expected + ", got '" + text + "'");
    }
    return value;
}

// What --direction, --azimuth, --elevation and --zoom ask for.
render::ViewChange parseViewChange(const Framing& framing) {
    const auto any = [](float) { return true; };
    render::ViewChange change;
    if (!framing.azimuth.empty()) {
        change.azimuth = parseNumber(framing.azimuth, "--azimuth", "degrees", any);
    }
    if (!framing.elevation.empty()) {
        change.elevation = parseNumber(framing.elevation, "--elevation", "degrees", any);
    }
    if (!framing.zoom.empty()) {
        change.zoom = parseNumber(framing.zoom, "--zoom", "a magnification > 0",
                                  [](float value) { return value > 0.0f; });
    }
    if (!framing.direction.empty()) {
        change.direction = parseDirection(framing.direction);
    }
    if (!framing.up.empty()) {
        change.up = parseDirection(framing.up, "--up");
    }
    return change;
}

} // namespace

glm::ivec2 parseSize(const std::string& text, const std::string& option) {
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
        throw DataError(option + ": expected WxH with whole numbers from 1 to 16384, got '" +
                        text + "'");
    }
    return size;
}

glm::vec3 parseDirection(const std::string& text, const std::string& option) {
    const std::optional<glm::vec3> direction = parseThreeNumbers(text);
    if (!direction || *direction == glm::vec3(0.0f)) {
        throw DataError(option + ": expected three numbers x,y,z not all zero, got '" + text +
                        "'");
    }
    return *direction;
}

namespace {

// "black", "white" or "r,g,b" (0 to 1) as an opaque colour; nothing for other text.
std::optional<glm::vec4> opaqueColorNamed(const std::string& text) {
    if (text == "black") {
        return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    }
    if (text == "white") {
        return glm::vec4(1.0f);
    }
    const glm::vec3 color = parseThreeNumbers(text).value_or(glm::vec3(-1.0f));
    const bool inRange = color.r >= 0.0f && color.r <= 1.0f && color.g >= 0.0f &&
                         color.g <= 1.0f && color.b >= 0.0f && color.b <= 1.0f;
    return inRange ? std::optional<glm::vec4>(glm::vec4(color, 1.0f)) : std::nullopt;
}

} // namespace

glm::vec4 parseBackground(const std::string& text) {
    if (text == "transparent") {
        return glm::vec4(0.0f);
    }
    if (const std::optional<glm::vec4> color = opaqueColorNamed(text)) {
        return *color;
    }
    throw DataError("--background: expected black, white, transparent or r,g,b (0 to 1), "
                    "got '" + text + "'");
}

glm::vec4 parseOpaqueColor(const std::string& text, const std::string& option) {
    if (const std::optional<glm::vec4> color = opaqueColorNamed(text)) {
        return *color;
    }
    throw DataError(option + ": expected black, white or r,g,b (0 to 1), got '" + text +
                    "'");
}

namespace {

struct ParsedBudget {
    std::optional<std::int32_t> maxSplats;
    std::optional<float> errorThreshold;
};

ParsedBudget parseBudget(const BudgetOverride& budget) {
    ParsedBudget parsed;
    if (!budget.maxSplats.empty()) {
        const bool isWhole = budget.maxSplats.size() <= 9 &&
                             std::all_of(budget.maxSplats.begin(), budget.maxSplats.end(),
                                         [](char c) { return c >= '0' && c <= '9'; });
        if (!isWhole) {
            throw DataError("--max-splats: expected a whole number from 0 (no budget) to "
                            "999999999, got '" + budget.maxSplats + "'");
        }
        parsed.maxSplats = std::stoi(budget.maxSplats);
    }
    if (!budget.errorThreshold.empty()) {
        parsed.errorThreshold =
            parseNumber(budget.errorThreshold, "--error-threshold",
                        "a finite number >= 0 (0: full resolution)",
                        [](float value) { return value >= 0.0f; });
    }
    return parsed;
}

} // namespace

void checkSceneOptions(const Framing& framing, const BudgetOverride& budget) {
    parseBudget(budget);
    parseViewChange(framing);
    parseFramingCamera(framing.camera);
}

render::FramingCamera parseFramingCamera(const std::string& camera) {
    if (camera.empty() || camera == "perspective") {
        return render::FramingCamera::Perspective;
    }
    if (camera == "orthographic") {
        return render::FramingCamera::Orthographic;
    }
    throw DataError("--camera: expected 'perspective' or 'orthographic', got '" + camera + "'");
}

int applyBudget(sg::Node& scene, const BudgetOverride& budget) {
    if (budget.maxSplats.empty() && budget.errorThreshold.empty()) {
        return 0;
    }
    const ParsedBudget parsed = parseBudget(budget);
    sg::SearchAction search;
    search.setType(nodes::ScalarSplat::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.apply(scene);
    if (search.paths().empty()) {
        throw DataError("--max-splats/--error-threshold: the scene has no splat node to set");
    }
    for (const sg::Path& path : search.paths()) {
        auto& splat = static_cast<nodes::ScalarSplat&>(*path.tail());
        if (parsed.maxSplats) {
            splat.maxSplats.setValue(*parsed.maxSplats);
        }
        if (parsed.errorThreshold) {
            splat.errorThreshold.setValue(*parsed.errorThreshold);
        }
    }
    return static_cast<int>(search.paths().size());
}

sg::Node::Ptr loadScene(const SceneSource& source) {
    nodes::registerNodeTypes();
    sg::registerEngineTypes(sg::NodeRegistry::instance());
    const std::string& path = source.path;
    if (path.empty()) {
        return sg::Node::Ptr(nodes::makeDefaultScene());
    }
    sg::SceneReader::ReadOptions options;
    options.dataRoots = source.dataRoots;
    if (!source.headerless &&
        volume::detectVolumeFileFormat(path) == volume::VolumeFileFormat::Unknown) {
        return sg::SceneReader::readFile(path, options);
    }
    // A data file in place of a scene: a first look, with the scene `info --scene` prints.
    if (source.dataRoots) {
        source.dataRoots->check(path, "data file");
    }
    const std::string info = "texsplat info " + path + source.headerlessArguments + " --scene";
    std::fprintf(stderr,
                 "texsplat: %s is a data file: drawing it with the scene `%s` prints; to edit "
                 "it, save it (%s > scene.iv) and render scene.iv\n",
                 path.c_str(), info.c_str(), info.c_str());
    return sg::SceneReader::readString(volume::quickLookScene(path, source.headerless),
                                       "scene of " + path, options);
}

sg::Node::Ptr loadScene(const std::string& path) {
    SceneSource source;
    source.path = path;
    return loadScene(source);
}

void addViewOptions(CLI::App& command, Framing& framing) {
    command.add_option("--camera", framing.camera,
                       "perspective|orthographic: the camera that frames a scene without one "
                       "(default perspective, 30 degrees high), or the scene's own camera made "
                       "that kind, seeing the same at its focal distance");
    command.add_option("--direction", framing.direction,
                       "x,y,z: viewing direction, of the camera that frames a scene without one "
                       "(default 0,0,-1: from +z) or of the scene's own camera (turned about its "
                       "focal point)");
    command.add_option("--up", framing.up,
                       "x,y,z: the direction that is up in the image (default: +y for a view "
                       "along -z; for others the smallest turn from that view)");
    command.add_option("--azimuth", framing.azimuth,
                       "Degrees to orbit the camera about its up axis through its focal point")
        ->type_name("DEG");
    command.add_option("--elevation", framing.elevation,
                       "Degrees to orbit the camera up about its right axis, after --azimuth")
        ->type_name("DEG");
    command.add_option("--zoom", framing.zoom, "Magnification (2: twice as large)")
        ->type_name("F");
}

sg::Node::Ptr withCamera(const sg::Node::Ptr& scene, const Framing& framing, float aspect,
                         const sg::WorkProgress& progress) {
    const render::ViewChange change = parseViewChange(framing);
    nodes::Camera* camera = render::findCamera(*scene);
    if (camera && !framing.camera.empty()) {
        // The scene's camera, of the kind asked for, seeing the same at its focal distance.
        render::replaceCamera(*scene, *camera,
                              render::cameraOfKind(*camera, parseFramingCamera(framing.camera)));
    }
    render::Framing frame;
    frame.camera = parseFramingCamera(framing.camera);
    frame.direction = framing.sceneName.empty() ? kDefaultSceneDirection
                                                : glm::vec3(0.0f, 0.0f, -1.0f);
    frame.name = framing.sceneName.empty() ? "default scene" : framing.sceneName;
    frame.progress = progress;
    try {
        return render::viewedScene(scene, aspect, frame, change);
    } catch (const DataError& error) {
        // An up along the view is told in the option's words.
        const std::string message = error.what();
        if (camera && message.rfind("up: ", 0) == 0) {
            throw DataError("--up: " + framing.up + ": " + message.substr(4));
        }
        throw;
    }
}

} // namespace texsplat::apps
