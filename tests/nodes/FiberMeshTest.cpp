#include "nodes/FiberMesh.h"

#include "SceneNodesTestSupport.h"
#include "nodes/Fibers.h"
#include "nodes/Material.h"
#include "nodes/VolumeData.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::nodes {
namespace {

using test::errorOf;

TEST(FiberMesh, buildsAClosedCylinderPerFiber) {
    volume::Fiber fiber;
    fiber.start = glm::dvec3(0.0, 0.0, 0.0);
    fiber.end = glm::dvec3(0.0, 0.0, 2.0);
    fiber.radius = 0.5;
    const TriangleMesh mesh = fiberMesh({fiber}, 8, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(mesh.triangleCount(), 32u);       // 2 per side segment, 1 per cap segment
    EXPECT_EQ(mesh.positions.size(), 16u + 18u); // side ring pairs, two caps with centres
    const sg::Box3 bounds = mesh.bounds();
    EXPECT_NEAR(bounds.min().z, 0.0f, 1e-6f);
    EXPECT_NEAR(bounds.max().z, 2.0f, 1e-6f);
    EXPECT_NEAR(bounds.max().x, 0.5f, 1e-6f);
    for (const glm::vec3& position : mesh.positions) {
        const float distance = glm::length(glm::vec2(position));
        EXPECT_TRUE(std::abs(distance - 0.5f) < 1e-6f || distance < 1e-6f);
    }
    // Every triangle faces the way its vertex normals point: outward.
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[i]];
        const glm::vec3& b = mesh.positions[mesh.indices[i + 1]];
        const glm::vec3& c = mesh.positions[mesh.indices[i + 2]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_GT(glm::dot(face, mesh.normals[mesh.indices[i + k]]), 0.0f) << i;
        }
    }
    EXPECT_EQ(mesh.colors, std::vector<glm::vec3>(34, glm::vec3(1.0f, 0.0f, 0.0f)));
}

TEST(FiberMesh, reportsBadInput) {
    EXPECT_EQ(errorOf<DataError>([] { fiberMesh({}, 2, glm::vec3(1.0f)); }),
              "fiberMesh(): a cylinder needs at least 3 segments, got 2");
    volume::Fiber point;
    point.end = point.start;
    EXPECT_EQ(errorOf<DataError>([&] { fiberMesh({volume::Fiber(), point}, 6, glm::vec3(1.0f)); }),
              "fiberMesh(): fiber 1 needs finite, distinct start and end points");
    volume::Fiber thin;
    thin.radius = 0.0;
    EXPECT_EQ(errorOf<DataError>([&] { fiberMesh({thin}, 6, glm::vec3(1.0f)); }),
              "fiberMesh(): fiber 0 needs a finite, positive radius, got 0");
}

TEST(Fibers, drawsTheAerogelFibersOfTheCurrentVolume) {
    const auto root = sg::Separator::create();
    const auto volume = VolumeData::create();
    volume->source.setValue(VolumeSource::Aerogel);
    volume->resolution = glm::vec3(6.0f);
    const auto material = Material::create();
    material->diffuseColor.setValue({glm::vec3(0.1f, 0.2f, 0.3f)});
    const auto fibers = Fibers::create();
    fibers->segments = 6;
    const auto probe = test::StateProbe::create();
    TriangleMesh mesh;
    probe->visit = [&](sg::Action& action) { mesh = fibers->triangleMesh(action.state()); };
    root->addChild(volume);
    root->addChild(material);
    root->addChild(fibers);
    root->addChild(probe);
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(mesh.triangleCount(), 24u * 4u * 6u);
    EXPECT_EQ(mesh.colors.front(), glm::vec3(0.1f, 0.2f, 0.3f));
    // The box holds the volume and the fibers (which may stick out of the unit cube).
    const sg::Box3 fiberBox = mesh.bounds();
    sg::Box3 expected = volume->bounds();
    expected.extendBy(fiberBox);
    EXPECT_EQ(action.boundingBox(), expected);
}

TEST(Fibers, needsAVolumeBefore) {
    const auto root = sg::Separator::create();
    root->addChild(Fibers::create());
    sg::BoundingBoxAction action;
    EXPECT_EQ(errorOf<DataError>([&] { action.apply(*root); }),
              "Fibers: no VolumeData before it; the fibers come from its AEROGEL source");
}

} // namespace
} // namespace texsplat::nodes
