#pragma once

#include "nodes/annotation/ColorLegend.h"
#include "nodes/image/Image.h"
#include "scenegraph/Node.h"

#include <glm/vec4.hpp>

#include <optional>
#include <string>

namespace CLI {
class App;
} // namespace CLI

namespace texsplat::apps {

/// @brief The options of `texsplat render` that draw into the image after rendering, so that
/// every backend and the ray caster get the same figure.
struct AnnotationOptions {
    bool colorbar = false;                 ///< --colorbar
    std::string colorbarPosition = "right"; ///< --colorbar-position
    bool outline = false;                  ///< --outline
    std::string outlineColor = "white";    ///< --outline-color
};

/// @brief Adds --colorbar, --colorbar-position, --outline and --outline-color to `command`.
void addAnnotationOptions(CLI::App& command, AnnotationOptions& options);

/// @brief What `texsplat render` draws into each image: the volumes' outline
/// (annotation::VolumeOutline, per frame, with the frame's camera) and, over it, the colour
/// legend (annotation::ColorLegend).
class ImageAnnotations {
public:
    /// @brief The annotations `options` ask for on the scene under `root` as it will be drawn.
    /// @throws DataError naming the option for a bad position or colour; what
    /// ColorLegend::ofScene() throws.
    ImageAnnotations(const AnnotationOptions& options, sg::Node& root);

    /// @brief Writes `image` to `path`, annotated (in a copy) when any annotation was asked for.
    /// The outline uses the scene's camera as it is now: call it after rendering the frame.
    void write(const image::Image& image, const std::string& path) const;

private:
    sg::Node& mRoot;
    std::optional<annotation::ColorLegend> mLegend;
    std::optional<glm::vec4> mOutlineColor;
};

} // namespace texsplat::apps
