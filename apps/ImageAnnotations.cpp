#include "apps/ImageAnnotations.h"

#include "apps/SceneSetup.h"
#include "scenegraph/Error.h"

#include <CLI/CLI.hpp>

namespace texsplat::apps {

void addAnnotationOptions(CLI::App& command, AnnotationOptions& options) {
    CLI::Option* colorbar = command.add_flag(
        "--colorbar", options.colorbar,
        "Draw colour bars beside the picture: one per transfer function and quantity the splat "
        "nodes colour by, with round tick values and the TransferFunction's title and units");
    command
        .add_option("--colorbar-position", options.colorbarPosition,
                    "The side of the image the colour bars take: right, left, top or bottom")
        ->capture_default_str();
    command
        .add_option("--colorbar-title", options.colorbarTitles,
                    "Title of a colour bar, instead of its TransferFunction's title and units "
                    "(\"\": none); once per bar, in the bars' order")
        ->type_name("TEXT")
        ->allow_extra_args(false)
        ->needs(colorbar);
    command
        .add_option("--colorbar-ticks", options.colorbarTicks,
                    "How many tick values each colour bar aims for (2 to 20)")
        ->capture_default_str()
        ->needs(colorbar);
    CLI::Option* outline =
        command.add_flag("--outline", options.outline,
                         "Draw the 12 edges of each splat node's volume box, seen by the scene's "
                         "camera: the edges behind the volume under it, the others over it");
    command
        .add_option("--outline-color", options.outlineColor,
                    "Colour of --outline: black, white or r,g,b (0 to 1, as colour maps give "
                    "them)")
        ->capture_default_str()
        ->needs(outline);
}

annotation::AnnotationRequest annotationRequest(const AnnotationOptions& options,
                                                const glm::vec4& background) {
    annotation::AnnotationRequest request;
    request.background = background;
    request.layered = true; // rendered over request.renderBackground()
    if (options.outline) {
        request.outline = parseOpaqueColor(options.outlineColor, "--outline-color");
    }
    try {
        request.colorbarPosition = annotation::parseLegendPosition(options.colorbarPosition);
    } catch (const DataError& error) {
        throw DataError(std::string("--colorbar-position: ") + error.what());
    }
    if (options.colorbarTicks < 2 || options.colorbarTicks > annotation::LegendStyle::kMaxTicks) {
        throw DataError("--colorbar-ticks: expected 2 to " +
                        std::to_string(annotation::LegendStyle::kMaxTicks) + ", got " +
                        std::to_string(options.colorbarTicks));
    }
    request.colorbarTicks = options.colorbarTicks;
    request.colorbar = options.colorbar;
    return request;
}

annotation::ImageAnnotations imageAnnotations(const AnnotationOptions& options, sg::Node& root,
                                              const glm::vec4& background) {
    annotation::ImageAnnotations annotations(annotationRequest(options, background), root);
    try {
        annotations.setBarTitles(options.colorbarTitles);
    } catch (const DataError& error) {
        throw DataError(std::string("--colorbar-title: ") + error.what());
    }
    return annotations;
}

} // namespace texsplat::apps
