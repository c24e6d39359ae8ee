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
/// are opaque, `max(1, side / 256)` pixels wide.
///
/// An edge between two faces that both face away from the camera lies behind the volume: it is
/// drawn behind it (Edges::Behind, under the rendered layer, so the volume hides it where it is
/// opaque), the others in front (Edges::InFront), as a box of glass would show them.
class VolumeOutline {
public:
    /// @brief An edge in pixel coordinates: x to the right, y down from the top row, pixel
    /// (i, j) centred at (i + 0.5, j + 0.5).
    struct Segment {
        glm::vec2 from;
        glm::vec2 to;
        bool isBehind = false; ///< both faces of the edge face away from the camera
    };

    /// @brief Which edges draw() draws.
    enum class Edges { All, InFront, Behind };

    /// @brief The outline of the splat nodes under `root` in an image of `width` × `height`, in
    /// the premultiplied colour `rgba`.
    /// @throws DataError as rendering does: a splat node without a camera before it, unusable
    /// camera fields; what reading a volume throws.
    static VolumeOutline ofScene(sg::Node& root, int width, int height, const glm::vec4& rgba);

    /// @brief The visible parts of the edges.
    const std::vector<Segment>& segments() const { return mSegments; }

    /// @brief Draws the `which` edges into `image` (of the size given to ofScene()), replacing
    /// the pixels they cover.
    void draw(image::Image& image, Edges which = Edges::All) const;

private:
    std::vector<Segment> mSegments;
    glm::vec4 mColor{1.0f};
};

} // namespace texsplat::annotation
