// Property test over extreme scenes (issue 14; docs/design.md, "Numerics"): randomized scenes,
// from a fixed seed, of extreme data (NaN, ±Inf, ±FLT_MAX, denormals), opacities from 1e-8 to
// 1e8, emission up to 3e38, cameras inside the volume, on its boundary and at grazing angles,
// images of 1×1 and 1×4096 pixels, tiny and huge transforms, drawn by the CPU backend, the GL
// backend and the ray caster. The property: never a NaN or infinite pixel, never a crash; an
// input that cannot be drawn ends in an error that names the scene file.

#include "GlTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/RayCastImage.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/render/gl/GlRenderer.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/actions/RayCastAction.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

constexpr int kScenes = 48;
constexpr std::uint32_t kSeed = 20261126;

using Random = std::mt19937;

template <class T> const T& pick(Random& random, const std::vector<T>& choices) {
    return choices[std::uniform_int_distribution<std::size_t>(0, choices.size() - 1)(random)];
}

float logUniform(Random& random, float low, float high) {
    const float exponent =
        std::uniform_real_distribution<float>(std::log10(low), std::log10(high))(random);
    return std::pow(10.0f, exponent);
}

// Text of a float that reads back to the same float.
std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
    return text;
}

std::string vector3(const glm::vec3& value) {
    return number(value.x) + " " + number(value.y) + " " + number(value.z);
}

// One voxel value: mostly ordinary, often extreme.
float voxelValue(Random& random) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    constexpr float kMax = std::numeric_limits<float>::max();
    static const std::vector<float> kExtremes{
        std::numeric_limits<float>::quiet_NaN(), kInf, -kInf, kMax, -kMax,
        std::numeric_limits<float>::denorm_min(), -1e-40f, std::numeric_limits<float>::min(),
        1e30f, -1e30f, 0.0f};
    if (std::uniform_real_distribution<float>(0.0f, 1.0f)(random) < 0.3f) {
        return pick(random, kExtremes);
    }
    return std::uniform_real_distribution<float>(0.0f, 1.0f)(random);
}

// A raw volume of extreme values; answers its path.
std::string writeVolume(Random& random, int index, glm::ivec3 dims, float spacing) {
    const std::string path =
        ::testing::TempDir() + "texsplat_extreme_" + std::to_string(index) + ".raw";
    std::ofstream file(path, std::ios::binary);
    file << "texsplat-raw 1\ndims " << dims.x << " " << dims.y << " " << dims.z
         << "\ntype float32\nspacing " << number(spacing) << " " << number(spacing) << " "
         << number(spacing) << "\ndata\n";
    for (int voxel = 0; voxel < dims.x * dims.y * dims.z; ++voxel) {
        const float value = voxelValue(random);
        file.write(reinterpret_cast<const char*>(&value), sizeof value);
    }
    return path;
}

std::string rotationText(const glm::vec3& direction) {
    const sg::Rotation rotation = render::rotationLookingAlong(direction);
    return vector3(rotation.axis()) + " " + number(rotation.angle());
}

struct ExtremeScene {
    std::string name;
    std::string text;
    int width = 1;
    int height = 1;
};

// Scene `index`: a camera (or none: framed as `render` frames it) placed against the volume's
// box in world space, a Transform, a TransferFunction and a splat node over an extreme volume.
ExtremeScene makeScene(Random& random, int index) {
    const glm::ivec3 dims(pick(random, std::vector<int>{1, 2, 5, 8}),
                          pick(random, std::vector<int>{1, 3, 8}),
                          pick(random, std::vector<int>{1, 4, 8}));
    const float spacing = pick(random, std::vector<float>{0.25f, 1.0f, 3.0f});
    const std::string volume = writeVolume(random, index, dims, spacing);
    const float scale = pick(random, std::vector<float>{1e-30f, 1e-12f, 1e-3f, 1.0f, 1.0f, 1e3f,
                                                        1e12f, 1e30f});
    const glm::vec3 translation(scale * std::uniform_real_distribution<float>(-4.0f, 4.0f)(random));
    // The volume's box in world space, roughly: its cells from the origin.
    const glm::vec3 extent = glm::vec3(dims) * spacing * scale;
    const glm::vec3 centre = translation + 0.5f * extent;

    std::ostringstream text;
    text << "#Inventor V2.1 ascii\nSeparator {\n";
    const int placement = std::uniform_int_distribution<int>(0, 4)(random);
    const bool perspective = std::uniform_int_distribution<int>(0, 2)(random) != 0;
    glm::vec3 position = centre;
    glm::vec3 direction(0.0f, 0.0f, -1.0f);
    switch (placement) {
    case 0: // inside, looking anywhere
        direction = glm::vec3(std::normal_distribution<float>()(random),
                              std::normal_distribution<float>()(random),
                              std::normal_distribution<float>()(random));
        break;
    case 1: // on the boundary, looking in
        position.x = translation.x + extent.x;
        direction = glm::vec3(-1.0f, 0.1f, 0.05f);
        break;
    case 2: // outside, grazing a face
        position = centre + glm::vec3(0.0f, 0.5f * extent.y, 3.0f * extent.z + scale);
        direction = glm::vec3(0.0f, -1e-4f, -1.0f);
        break;
    case 3: // outside, exactly along an axis through the corner
        position = translation + glm::vec3(0.0f, 0.0f, 4.0f * extent.z + scale);
        break;
    default: // no camera: framed
        break;
    }
    if (placement < 4) {
        const float nearDistance = scale * pick(random, std::vector<float>{1e-3f, 0.1f, 1.0f});
        text << (perspective ? "PerspectiveCamera" : "OrthographicCamera") << " {\n"
             << "  position " << vector3(position) << "\n  orientation "
             << rotationText(direction) << "\n  nearDistance " << number(nearDistance)
             << "\n  farDistance " << number(nearDistance + 100.0f * scale * glm::length(
                                                                  glm::vec3(dims) * spacing))
             << "\n";
        if (!perspective) {
            text << "  height " << number(2.0f * glm::length(extent) + scale) << "\n";
        }
        text << "}\n";
    }
    text << "Transform { translation " << vector3(translation) << " scaleFactor "
         << vector3(glm::vec3(scale)) << " }\n";
    const float opacity = logUniform(random, 1e-8f, 1e8f);
    const float emission = pick(random, std::vector<float>{0.0f, 1.0f, 1e20f, 3e38f});
    text << "TransferFunction { preset HOT rangeMode "
         << pick(random, std::vector<std::string>{"FIXED", "DATA", "PERCENTILE"})
         << " range 0 1 opacityValues [ 0, 1 ] opacities [ 0, " << number(opacity)
         << " ] emission " << number(emission) << " }\n";
    text << "VolumeData { source FILE_RAW fileName \"" << volume << "\" }\n";
    text << pick(random, std::vector<std::string>{"TextureSplat { }", "TextureSplat { kernel "
                                                  "GAUSSIAN }", "TextureSplat { maxSplats 20 }",
                                                  "GaussianSplat { }"})
         << "\n}\n";
    static const std::vector<glm::ivec2> kSizes{{1, 1}, {1, 4096}, {4096, 1}, {7, 5}, {33, 17}};
    const glm::ivec2 size = pick(random, kSizes);
    return {"extreme-" + std::to_string(index) + ".iv", text.str(), size.x, size.y};
}

image::Image drawCpu(sg::Node& root, int width, int height) {
    render::FrameAction action(width, height);
    const render::cpu::CpuRenderer renderer(2);
    return renderer.draw(action.collect(root), action.statistics(), false);
}

image::Image drawGl(sg::Node& root, int width, int height) {
    render::FrameAction action(width, height);
    render::GlRenderer renderer;
    return renderer.draw(action.collect(root), action.statistics(), false);
}

image::Image drawRayCast(sg::Node& root, int width, int height) {
    sg::RayCastAction action(width, height);
    action.render(root);
    return render::rayCastImage(action);
}

struct Backend {
    const char* name;
    std::function<image::Image(sg::Node&, int, int)> draw;
    int drawn = 0;
    int refused = 0;
};

TEST(ExtremeSceneProperty, noBackendDrawsANanOrInfinitePixelOrCrashes) {
    test::sharedContext();
    registerNodeTypes();
    // The warnings of extreme scenes (a huge ray-cast estimate, clamped light) are expected.
    const LogSink previous = setLogSink({});
    std::array<Backend, 3> backends{Backend{"cpu", drawCpu}, Backend{"gl", drawGl},
                                    Backend{"raycast", drawRayCast}};
    Random random(kSeed);
    for (int index = 0; index < kScenes; ++index) {
        const ExtremeScene scene = makeScene(random, index);
        for (Backend& backend : backends) {
            SCOPED_TRACE(std::string(backend.name) + ", " + std::to_string(scene.width) + "x" +
                         std::to_string(scene.height) + ", " + scene.name + ":\n" + scene.text);
            try {
                const sg::Node::Ptr read = sg::SceneReader::readString(scene.text, scene.name);
                render::Framing framing;
                framing.name = scene.name;
                const sg::Node::Ptr root = render::framedScene(
                    read, static_cast<float>(scene.width) / static_cast<float>(scene.height),
                    framing);
                const image::Image image = backend.draw(*root, scene.width, scene.height);
                EXPECT_EQ(image.statistics().nonFinitePixels, 0u);
                ++backend.drawn;
            } catch (const Error& error) {
                // Refused: the message must say where, the scene file (and line).
                const std::string message = error.what();
                EXPECT_EQ(message.rfind(scene.name + ":", 0), 0u) << message;
                ++backend.refused;
            }
        }
    }
    setLogSink(previous);
    for (const Backend& backend : backends) {
        std::printf("extreme scenes, %s: %d drawn, %d refused\n", backend.name, backend.drawn,
                    backend.refused);
        // Most extreme scenes are valid: the property must not hold vacuously.
        EXPECT_GE(backend.drawn, kScenes / 2) << backend.name;
    }
}

} // namespace
} // namespace texsplat::nodes
