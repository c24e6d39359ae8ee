#include "nodes/render/RenderedImage.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace texsplat::render {

image::Image renderedImage(sg::RenderAction& action, DepthReadback depth) {
    const gl::Framebuffer& framebuffer = action.framebuffer();
    image::Image result(framebuffer.width(), framebuffer.height());
    std::vector<float> rgba = action.readColor();
    // Light beyond FLT_MAX (+Inf once scaled back from what GL drew) is FLT_MAX, as on the CPU
    // backend and in the ray caster.
    for (float& value : rgba) {
        value = std::clamp(value, -std::numeric_limits<float>::max(),
                           std::numeric_limits<float>::max());
    }
    std::memcpy(result.data(), rgba.data(), rgba.size() * sizeof(float));
    if (depth == DepthReadback::With) {
        result.addDepth();
        const std::vector<float> depths = action.readDepth();
        std::copy(depths.begin(), depths.end(), result.depthData());
    }
    return result;
}

} // namespace texsplat::render
