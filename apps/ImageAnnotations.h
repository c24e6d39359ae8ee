#pragma once

#include "nodes/annotation/ImageAnnotations.h"
#include "scenegraph/Node.h"

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

/// @brief The annotations `options` ask for on the scene under `root` as it will be drawn.
/// @throws DataError naming the option for a bad position or colour; what
/// annotation::ColorLegend::ofScene() throws.
annotation::ImageAnnotations imageAnnotations(const AnnotationOptions& options, sg::Node& root);

} // namespace texsplat::apps
