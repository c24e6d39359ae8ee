#pragma once

#include "nodes/image/Image.h"
#include "scenegraph/Node.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace texsplat::annotation {

/// @brief The outline of the volumes a scene draws: the 12 edges of the box of each splat node's
/// VolumeData, seen by the camera that renders that node, drawn into a rendered image (after
/// the render, as ColorLegend, so every backend and the ray caster get the same lines).
///
/// The boxes are the splat nodes' bounding boxes (the volume's bounds under the model matrix
/// where the splat node stands) and the camera is render::CameraView::current() at the node,
/// what every backend projects the splats with; edges are clipped to the view volume. Lines
/// are opaque, drawn over the image (not hidden by the volume), `max(1, side / 256)` pixels wide.
class VolumeOutline {
public:
    /// @brief An edge in pixel coordinates: x to the right, y down from the top row, pixel
    /// (i, j) centred at (i + 0.5, j + 0.5).
    struct Segment {
        glm::vec2 from;
        glm::vec2 to;
    };

    /// @brief The outline of the splat nodes under `root` in an image of `width` × `height`, in
    /// the premultiplied colour `rgba`.
    /// @throws DataError as rendering does: a splat node without a camera before it, unusable
    /// camera fields; what reading a volume throws.
    static VolumeOutline ofScene(sg::Node& root, int width, int height, const glm::vec4& rgba);

    /// @brief The visible parts of the edges.
    const std::vector<Segment>& segments() const { return mSegments; }

    /// @brief Draws the edges into `image` (of the size given to ofScene()), replacing the pixels
    /// they cover.
    void draw(image::Image& image) const;

private:
    std::vector<Segment> mSegments;
    glm::vec4 mColor{1.0f};
};

} // namespace texsplat::annotation
