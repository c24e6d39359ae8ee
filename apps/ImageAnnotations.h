#pragma once

#include "nodes/annotation/ImageAnnotations.h"
#include "scenegraph/Node.h"

#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace CLI {
class App;
} // namespace CLI

namespace texsplat::apps {

/// @brief The options of `texsplat render` that make a figure of the rendered picture: the
/// colour bars beside it and the volumes' outline, the same for every backend and the ray
/// caster.
struct AnnotationOptions {
    bool colorbar = false;                   ///< --colorbar
    std::string colorbarPosition = "right";  ///< --colorbar-position
    std::vector<std::string> colorbarTitles; ///< --colorbar-title, once per bar
    int colorbarTicks = 5;                   ///< --colorbar-ticks
    bool outline = false;                    ///< --outline
    std::string outlineColor = "white";      ///< --outline-color
};

/// @brief Adds --colorbar, --colorbar-position, --colorbar-title, --colorbar-ticks, --outline
/// and --outline-color to `command`.
void addAnnotationOptions(CLI::App& command, AnnotationOptions& options);

/// @brief What `options` ask for, for a picture composited over `background` (premultiplied) and
/// rendered over the request's renderBackground() (layered).
/// @throws DataError naming the option for a bad position, tick count or colour.
annotation::AnnotationRequest annotationRequest(const AnnotationOptions& options,
                                                const glm::vec4& background);

/// @brief The annotations `options` ask for on the scene under `root` as it will be drawn, over
/// `background`.
/// @throws DataError naming the option for a bad position, tick count, colour, or more titles
/// than bars; what annotation::ColorBar::ofScene() throws.
annotation::ImageAnnotations imageAnnotations(const AnnotationOptions& options, sg::Node& root,
                                              const glm::vec4& background);

} // namespace texsplat::apps
