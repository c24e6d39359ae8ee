#include "nodes/render/SceneImage.h"

#include "nodes/render/FrameAction.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"

#include <cstdint>
#include <string>

namespace texsplat::render {

image::Image sceneImage(const sg::Node::Ptr& scene, const SceneImageOptions& options) {
    if (options.width < 1 || options.height < 1) {
        throw DataError("sceneImage(): the image must be at least 1 x 1 pixels, got " +
                        std::to_string(options.width) + " x " + std::to_string(options.height));
    }
    // Asked before rendering, as every stage asks for its largest allocation: the image (the
    // CPU backend's colour planes are as large).
    const std::uint64_t pixels = std::uint64_t(options.width) * std::uint64_t(options.height);
    checkMemory("sceneImage(): rendering a " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + " image",
                byteProduct(pixels, sizeof(glm::vec4)), "render a smaller image");
    const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
    const sg::Node::Ptr root = framedScene(scene, aspect);
    FrameAction action(options.width, options.height, options.background);
    const cpu::CpuRenderer renderer(options.threads);
    return renderer.draw(action.collect(*root), action.statistics(), false);
}

} // namespace texsplat::render
