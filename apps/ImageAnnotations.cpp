#include "apps/ImageAnnotations.h"

#include "apps/SceneSetup.h"
#include "scenegraph/Error.h"

#include <CLI/CLI.hpp>

namespace texsplat::apps {

void addAnnotationOptions(CLI::App& command, AnnotationOptions& options) {
    command.add_flag("--colorbar", options.colorbar,
                     "Draw a legend of the colours of the first splat node's TransferFunction, "
                     "with the values of its range over that node's data, into the image");
    command
        .add_option("--colorbar-position", options.colorbarPosition,
                    "Where --colorbar draws the legend: right, left, top or bottom")
        ->capture_default_str();
    CLI::Option* outline =
        command.add_flag("--outline", options.outline,
                         "Draw the 12 edges of each splat node's volume box into the image, seen "
                         "by the scene's camera");
    command
        .add_option("--outline-color", options.outlineColor,
                    "Colour of --outline: black, white or r,g,b (linear, 0 to 1)")
        ->capture_default_str()
        ->needs(outline);
}

annotation::ImageAnnotations imageAnnotations(const AnnotationOptions& options, sg::Node& root) {
    annotation::AnnotationRequest request;
    if (options.outline) {
        request.outline = parseOpaqueColor(options.outlineColor, "--outline-color");
    }
    if (options.colorbar) {
        try {
            request.colorbar = annotation::parseLegendPosition(options.colorbarPosition);
        } catch (const DataError& error) {
            throw DataError(std::string("--colorbar-position: ") + error.what());
        }
    }
    return annotation::ImageAnnotations(request, root);
}

} // namespace texsplat::apps
