#include "nodes/render/RayCastImage.h"

#include <cstring>

namespace texsplat::render {

image::Image rayCastImage(const sg::RayCastAction& action) {
    image::Image result(action.width(), action.height());
    const std::vector<float> rgba = action.readColor();
    std::memcpy(result.data(), rgba.data(), rgba.size() * sizeof(float));
    return result;
}

} // namespace texsplat::render
