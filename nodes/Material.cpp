#include "nodes/Material.h"

#include "nodes/detail/ColorText.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/elements/MaterialElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/fields/ValueFormat.h"

#include <cmath>
#include <vector>

namespace texsplat::nodes {

Material::Material() {
    const MaterialElement defaults;
    // Inventor's defaults; the ones texsplat uses come from MaterialElement.
    addField(ambientColor, "ambientColor", std::vector<glm::vec3>{glm::vec3(0.2f)},
             "Reflected ambient light; read and written back, not used");
    addField(diffuseColor, "diffuseColor", std::vector<glm::vec3>{defaults.diffuseColor},
             "Colour of the meshes under light (the first value is used); not of splats");
    addField(specularColor, "specularColor", std::vector<glm::vec3>{glm::vec3(0.0f)},
             "Highlight colour; read and written back, not used");
    addField(emissiveColor, "emissiveColor", std::vector<glm::vec3>{defaults.emissiveColor},
             "Colour the meshes emit without light (the first value is used)");
    addField(shininess, "shininess", std::vector<float>{0.2f},
             "Sharpness of highlights, 0 to 1; read and written back, not used");
    addField(transparency, "transparency", std::vector<float>{defaults.transparency},
             "0 opaque to 1 invisible, of the meshes (the first value is used)");
}

void Material::doAction(sg::Action& action) {
    // Check before modifying, so that a bad value leaves the state as it was.
    for (const sg::MFColor* color : {&diffuseColor, &emissiveColor}) {
        if (color->isEmpty()) {
            continue;
        }
        const glm::vec3& rgb = (*color)[0];
        if (!detail::isFiniteColor(rgb)) {
            throw DataError(detail::nodeContext(*this) + ": " + color->name() +
                            " must be finite, got " + detail::formatColor(rgb));
        }
    }
    if (!transparency.isEmpty() && !(transparency[0] >= 0.0f && transparency[0] <= 1.0f)) {
        throw DataError(detail::nodeContext(*this) + ": transparency must lie in [0, 1], got " +
                        sg::formatFloat(transparency[0]));
    }
    MaterialElement& element = action.state().modify<MaterialElement>();
    if (!diffuseColor.isEmpty()) {
        element.diffuseColor = diffuseColor[0];
    }
    if (!emissiveColor.isEmpty()) {
        element.emissiveColor = emissiveColor[0];
    }
    if (!transparency.isEmpty()) {
        element.transparency = transparency[0];
    }
}

} // namespace texsplat::nodes
