#include "nodes/Material.h"

#include "nodes/detail/NodeContext.h"
#include "nodes/elements/MaterialElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"

#include <cmath>

namespace texsplat::nodes {

Material::Material() {
    const MaterialElement defaults;
    addField(diffuseColor, "diffuseColor", defaults.diffuseColor);
    addField(emissiveColor, "emissiveColor", defaults.emissiveColor);
    addField(transparency, "transparency", defaults.transparency);
}

void Material::doAction(sg::Action& action) {
    for (const sg::SFColor* color : {&diffuseColor, &emissiveColor}) {
        const glm::vec3& rgb = color->value();
        if (!std::isfinite(rgb.r) || !std::isfinite(rgb.g) || !std::isfinite(rgb.b)) {
            throw DataError(detail::nodeContext(*this) + ": " + color->name() +
                            " must be finite, got " + color->valueText());
        }
    }
    const float t = transparency.value();
    if (!(t >= 0.0f && t <= 1.0f)) {
        throw DataError(detail::nodeContext(*this) + ": transparency must lie in [0, 1], got " +
                        transparency.valueText());
    }
    action.state().modify<MaterialElement>() =
        MaterialElement{diffuseColor.value(), emissiveColor.value(), t};
}

} // namespace texsplat::nodes
