#include "nodes/render/RenderedImage.h"

#include <algorithm>
#include <cstring>

namespace texsplat::render {

image::Image renderedImage(sg::RenderAction& action, DepthReadback depth) {
    const gl::Framebuffer& framebuffer = action.framebuffer();
    image::Image result(framebuffer.width(), framebuffer.height());
    const std::vector<float> rgba = action.readColor();
    std::memcpy(result.data(), rgba.data(), rgba.size() * sizeof(float));
    if (depth == DepthReadback::With) {
        result.addDepth();
        const std::vector<float> depths = action.readDepth();
        std::copy(depths.begin(), depths.end(), result.depthData());
    }
    return result;
}

} // namespace texsplat::render
