#pragma once

#include "nodes/image/ImageRegion.h"
#include "nodes/image/Pixels.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace texsplat::distributed {

/// @brief Part of an image: premultiplied RGBA pixels over a region of it, transparent outside.
/// What a rank draws of its brick (the brick's screen footprint) and what compositing passes on.
struct ImageLayer {
    image::ImageRegion region;     ///< where the pixels lie in the image; empty: nothing drawn
    image::Pixels pixels; ///< region.width x region.height, top row first

    /// @brief Whether the layer holds no pixel.
    bool isEmpty() const { return region.width <= 0 || region.height <= 0; }

    /// @brief The pixel at image position (x, y), inside region.
    const glm::vec4& at(int x, int y) const {
        return pixels[static_cast<std::size_t>(y - region.y) *
                          static_cast<std::size_t>(region.width) +
                      static_cast<std::size_t>(x - region.x)];
    }
};

/// @brief The pixels common to two regions (an empty region when they do not meet).
inline image::ImageRegion intersect(const image::ImageRegion& a, const image::ImageRegion& b) {
    const int x0 = a.x > b.x ? a.x : b.x;
    const int y0 = a.y > b.y ? a.y : b.y;
    const int x1 = a.x + a.width < b.x + b.width ? a.x + a.width : b.x + b.width;
    const int y1 = a.y + a.height < b.y + b.height ? a.y + a.height : b.y + b.height;
    if (x1 <= x0 || y1 <= y0) {
        return {};
    }
    return {x0, y0, x1 - x0, y1 - y0};
}

} // namespace texsplat::distributed
