#pragma once

#include "nodes/annotation/ColorBar.h"
#include "nodes/annotation/ColorLegend.h"
#include "nodes/image/Image.h"
#include "scenegraph/Node.h"

#include <glm/vec4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace texsplat::annotation {

/// @brief What to make of a rendered picture, so that every backend and the ray caster get the
/// same figure: `texsplat render --colorbar --outline` and the Python module's
/// `Image.save(colorbar=True)`.
struct AnnotationRequest {
    bool colorbar = false;                             ///< colour bars beside the picture
    LegendPosition colorbarPosition = LegendPosition::Right; ///< the side they take
    int colorbarTicks = 5;                  ///< tick values each bar aims for (LegendStyle)
    std::optional<glm::vec4> outline;       ///< the volumes' outline (VolumeOutline), its colour
    /// @brief What the picture is shown over (premultiplied): the colour bars' strip is filled
    /// with it and their ink reads on it.
    glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};
    /// @brief Whether the picture is rendered over renderBackground(), the layer alone when an
    /// outline is asked for, so that the edges behind the volume go under it and `background`
    /// is composited here; otherwise (a picture already over its background, as the Python
    /// module's) every edge is drawn over it.
    bool layered = false;

    /// @brief What to render the picture over: transparent when `layered` and an outline is
    /// asked for, else `background`.
    glm::vec4 renderBackground() const {
        return layered && outline ? glm::vec4(0.0f) : background;
    }
};

/// @brief The annotations of a scene as it is drawn: the volumes' outline (per image, with the
/// scene's camera as it is then: the edges where two faces turned away from the camera meet
/// under a layered picture, the others over it; VolumeOutline) and the colour bars of the
/// scene's splat nodes (ColorBar::ofScene(), ColorLegend) in a strip beside the picture.
class ImageAnnotations {
public:
    /// @brief The annotations `request` asks for on the scene under `root` (which must outlive
    /// this object), the bars found now (ColorBar::ofScene()).
    /// @throws DataError for a tick count outside 2 to LegendStyle::kMaxTicks; what
    /// ColorBar::ofScene() throws.
    ImageAnnotations(const AnnotationRequest& request, sg::Node& root);

    /// @brief Replaces the first bars' titles by `titles` ("" for none), in the bars' order.
    /// @throws DataError "given 2 times, but the scene has 1 colour bar" for more titles than
    /// bars.
    void setBarTitles(const std::vector<std::string>& titles);

    /// @brief The figure of `picture` (rendered over the request's renderBackground()): the
    /// outline's back edges under it and the others over it (all over it unless layered), then
    /// the colour bars' strip added beside it. The outline uses the scene's camera as it is now:
    /// call it after rendering the frame.
    image::Image annotated(const image::Image& picture) const;

    /// @brief Writes annotated(`picture`) to `path` (image::writeImage()).
    void write(const image::Image& picture, const std::string& path) const;

private:
    sg::Node& mRoot;
    AnnotationRequest mRequest;
    std::vector<ColorBar> mBars;
};

} // namespace texsplat::annotation
