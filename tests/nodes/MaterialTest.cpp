#include "nodes/Material.h"

#include "SceneNodesTestSupport.h"
#include "nodes/DirectionalLight.h"
#include "nodes/Transform.h"
#include "nodes/elements/LightElement.h"
#include "nodes/elements/MaterialElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/Rotation.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <vector>

namespace texsplat::nodes {
namespace {

using test::errorOf;

// Traverses `root` and answers element E as the probe (added last) saw it.
template <class E> E elementAfter(const sg::Separator::Ptr& root) {
    const auto probe = test::StateProbe::create();
    E seen;
    probe->visit = [&](sg::Action& action) { seen = action.state().get<E>(); };
    root->addChild(probe);
    sg::BoundingBoxAction action;
    action.apply(*root);
    return seen;
}

TEST(Material, hasInventorsFieldsAndDefaults) {
    const auto material = Material::create();
    EXPECT_EQ(material->ambientColor.values(), std::vector<glm::vec3>{glm::vec3(0.2f)});
    EXPECT_EQ(material->diffuseColor.values(), std::vector<glm::vec3>{glm::vec3(0.8f)});
    EXPECT_EQ(material->specularColor.values(), std::vector<glm::vec3>{glm::vec3(0.0f)});
    EXPECT_EQ(material->emissiveColor.values(), std::vector<glm::vec3>{glm::vec3(0.0f)});
    EXPECT_EQ(material->shininess.values(), std::vector<float>{0.2f});
    EXPECT_EQ(material->transparency.values(), std::vector<float>{0.0f});
}

TEST(Material, setsTheMaterialElement) {
    const auto root = sg::Separator::create();
    const auto material = Material::create();
    material->diffuseColor.setValue({glm::vec3(1.0f, 0.5f, 0.0f)});
    material->emissiveColor.setValue({glm::vec3(0.0f, 0.0f, 0.2f)});
    material->transparency.setValue({0.25f});
    root->addChild(material);
    const auto seen = elementAfter<MaterialElement>(root);
    EXPECT_EQ(seen.diffuseColor, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(seen.emissiveColor, glm::vec3(0.0f, 0.0f, 0.2f));
    EXPECT_EQ(seen.transparency, 0.25f);
}

// Inventor's per-part lists: texsplat's meshes take one material, the first.
TEST(Material, usesTheFirstValueOfEachList) {
    const auto root = sg::Separator::create();
    const auto material = Material::create();
    material->diffuseColor.setValue({glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)});
    material->emissiveColor.setValue({glm::vec3(0.1f), glm::vec3(0.2f)});
    material->transparency.setValue({0.5f, 2.0f}); // only the first is checked: it is used
    root->addChild(material);
    const auto seen = elementAfter<MaterialElement>(root);
    EXPECT_EQ(seen.diffuseColor, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(seen.emissiveColor, glm::vec3(0.1f));
    EXPECT_EQ(seen.transparency, 0.5f);
}

// As in Coin: an empty list does not set its part of the material.
TEST(Material, anEmptyListKeepsTheMaterialBefore) {
    const auto root = sg::Separator::create();
    const auto first = Material::create();
    first->diffuseColor.setValue({glm::vec3(1.0f, 0.0f, 0.0f)});
    first->transparency.setValue({0.5f});
    const auto second = Material::create();
    second->diffuseColor.setValue({});
    second->transparency.setValue({});
    second->emissiveColor.setValue({glm::vec3(0.0f, 0.0f, 1.0f)});
    root->addChild(first);
    root->addChild(second);
    const auto seen = elementAfter<MaterialElement>(root);
    EXPECT_EQ(seen.diffuseColor, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(seen.emissiveColor, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(seen.transparency, 0.5f);
}

TEST(Material, staysInsideItsSeparator) {
    const auto root = sg::Separator::create();
    const auto inner = sg::Separator::create();
    const auto material = Material::create();
    material->diffuseColor.setValue({glm::vec3(1.0f, 0.0f, 0.0f)});
    inner->addChild(material);
    root->addChild(inner);
    EXPECT_EQ(elementAfter<MaterialElement>(root).diffuseColor, glm::vec3(0.8f));
}

TEST(Material, reportsBadValues) {
    const auto root = sg::Separator::create();
    const auto material = Material::create();
    material->setName("paint");
    material->transparency.setValue({1.5f});
    root->addChild(material);
    sg::BoundingBoxAction action;
    EXPECT_EQ(errorOf<DataError>([&] { action.apply(*root); }),
              "Material 'paint': transparency must lie in [0, 1], got 1.5");
    material->transparency.setValue({0.0f});
    material->emissiveColor.setValue({glm::vec3(0.0f, std::nanf(""), 0.0f), glm::vec3(1.0f)});
    EXPECT_EQ(errorOf<DataError>([&] { action.apply(*root); }),
              "Material 'paint': emissiveColor must be finite, got 0 nan 0");
}

TEST(DirectionalLight, addsItsRootSpaceDirectionWhenOn) {
    const auto root = sg::Separator::create();
    const auto transform = Transform::create();
    // A quarter turn about +y maps the default direction (0,0,-1) to (-1,0,0).
    transform->rotation = sg::Rotation(glm::vec3(0.0f, 1.0f, 0.0f), glm::half_pi<float>());
    const auto light = DirectionalLight::create();
    light->intensity = 0.5f;
    light->color = glm::vec3(1.0f, 0.5f, 0.0f);
    const auto off = DirectionalLight::create();
    off->on = false;
    root->addChild(transform);
    root->addChild(light);
    root->addChild(off);
    const LightElement lights = elementAfter<LightElement>(root);
    ASSERT_EQ(lights.lights.size(), 1u);
    EXPECT_NEAR(lights.lights[0].direction.x, -1.0f, 1e-6f);
    EXPECT_NEAR(lights.lights[0].direction.z, 0.0f, 1e-6f);
    EXPECT_EQ(lights.lights[0].color, glm::vec3(0.5f, 0.25f, 0.0f));
}

TEST(DirectionalLight, reportsAZeroDirection) {
    const auto root = sg::Separator::create();
    const auto light = DirectionalLight::create();
    light->direction = glm::vec3(0.0f);
    root->addChild(light);
    sg::BoundingBoxAction action;
    EXPECT_EQ(errorOf<DataError>([&] { action.apply(*root); }),
              "DirectionalLight: direction must be a finite, non-zero vector (after the model "
              "matrix), got 0 0 0");
}

} // namespace
} // namespace texsplat::nodes
