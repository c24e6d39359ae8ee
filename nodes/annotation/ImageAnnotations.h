#pragma once

#include "nodes/annotation/ColorLegend.h"
#include "nodes/image/Image.h"
#include "scenegraph/Node.h"

#include <glm/vec4.hpp>

#include <optional>
#include <string>

namespace texsplat::annotation {

/// @brief What to draw into a rendered image after rendering, so that every backend and the ray
/// caster get the same figure: `texsplat render --colorbar --outline` and the Python module's
/// `Image.save(colorbar=True)`.
struct AnnotationRequest {
    std::optional<LegendPosition> colorbar; ///< the colour legend (ColorLegend), where
    std::optional<glm::vec4> outline;       ///< the volumes' outline (VolumeOutline), its colour
};

/// @brief The annotations of a scene as it is drawn: the volumes' outline (per image, with the
/// scene's camera as it is then) and, over it, the colour legend of the scene's first splat node.
class ImageAnnotations {
public:
    /// @brief The annotations `request` asks for on the scene under `root` (which must outlive
    /// this object), the legend made now (ColorLegend::ofScene()).
    /// @throws what ColorLegend::ofScene() throws.
    ImageAnnotations(const AnnotationRequest& request, sg::Node& root);

    /// @brief `image` annotated (a copy; `image` itself when nothing was asked for). The outline
    /// uses the scene's camera as it is now: call it after rendering the frame.
    image::Image annotated(const image::Image& image) const;

    /// @brief Writes annotated(`image`) to `path` (image::writeImage()).
    void write(const image::Image& image, const std::string& path) const;

private:
    sg::Node& mRoot;
    std::optional<ColorLegend> mLegend;
    std::optional<glm::vec4> mOutlineColor;
};

} // namespace texsplat::annotation
