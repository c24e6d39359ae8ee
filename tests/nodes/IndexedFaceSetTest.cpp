#include "nodes/IndexedFaceSet.h"

#include "SceneNodesTestSupport.h"
#include "nodes/Coordinate3.h"
#include "nodes/Material.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <gtest/gtest.h>

namespace texsplat::nodes {
namespace {

using test::errorOf;

const std::vector<glm::vec3> kPoints = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                        {2, 0, 0}, {2, 0, 1}, {0, 0, 1}};

TEST(IndexedFaceSet, splitsPolygonsIntoTriangleFans) {
    const auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValue({0, 1, 2, 3, -1, 1, 4, 5, -1});
    const TriangleMesh mesh = faces->triangleMesh(kPoints, glm::vec3(0.5f, 0.25f, 1.0f));
    ASSERT_EQ(mesh.triangleCount(), 3u);
    EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6}));
    ASSERT_EQ(mesh.positions.size(), 7u); // each polygon has its own corners (flat shading)
    EXPECT_EQ(mesh.positions[3], kPoints[3]);
    EXPECT_EQ(mesh.positions[6], kPoints[5]);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(mesh.normals[i], glm::vec3(0.0f, 0.0f, 1.0f));
    }
    for (std::size_t i = 4; i < 7; ++i) {
        EXPECT_EQ(mesh.normals[i], glm::vec3(0.0f, -1.0f, 0.0f));
    }
    EXPECT_EQ(mesh.colors, std::vector<glm::vec3>(7, glm::vec3(0.5f, 0.25f, 1.0f)));
}

TEST(IndexedFaceSet, acceptsAMissingFinalSeparatorAndPentagons) {
    const auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValue({0, 4, 5, 6, 3});
    const TriangleMesh mesh = faces->triangleMesh(kPoints, glm::vec3(1.0f));
    EXPECT_EQ(mesh.triangleCount(), 3u);
    EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
}

TEST(IndexedFaceSet, reportsBadIndicesByPosition) {
    const auto faces = IndexedFaceSet::create();
    faces->setName("walls");
    faces->coordIndex.setValue({0, 1, 2, -1, 0, 1, 9, -1});
    EXPECT_EQ(errorOf<DataError>([&] { faces->triangleMesh(kPoints, glm::vec3(1.0f)); }),
              "IndexedFaceSet 'walls': coordIndex[6] = 9 is not a point index: the Coordinate3 "
              "has 7 points");
    faces->coordIndex.setValue({0, 1, -2, 3});
    EXPECT_EQ(errorOf<DataError>([&] { faces->triangleMesh(kPoints, glm::vec3(1.0f)); }),
              "IndexedFaceSet 'walls': coordIndex[2] = -2 is not a point index: only -1 (end of "
              "polygon) may be negative");
    faces->coordIndex.setValue({0, 1, 2, -1, 3, 4, -1});
    EXPECT_EQ(errorOf<DataError>([&] { faces->triangleMesh(kPoints, glm::vec3(1.0f)); }),
              "IndexedFaceSet 'walls': the polygon ending at coordIndex[6] has 2 points; a face "
              "needs at least 3");
    faces->coordIndex.setValue({-1});
    EXPECT_EQ(errorOf<DataError>([&] { faces->triangleMesh(kPoints, glm::vec3(1.0f)); }),
              "IndexedFaceSet 'walls': the polygon ending at coordIndex[0] has 0 points; a face "
              "needs at least 3");
}

TEST(IndexedFaceSet, usesTheStatesCoordinatesAndMaterial) {
    const auto root = sg::Separator::create();
    const auto coordinates = Coordinate3::create();
    coordinates->point.setValue(kPoints);
    const auto material = Material::create();
    material->diffuseColor.setValue({glm::vec3(0.0f, 1.0f, 0.0f)});
    const auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValue({1, 4, 5, -1});
    const auto probe = test::StateProbe::create();
    TriangleMesh mesh;
    probe->visit = [&](sg::Action& action) { mesh = faces->triangleMesh(action.state()); };
    root->addChild(coordinates);
    root->addChild(material);
    root->addChild(faces);
    root->addChild(probe);
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(),
              sg::Box3(glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(2.0f, 0.0f, 1.0f)));
    ASSERT_EQ(mesh.triangleCount(), 1u);
    EXPECT_EQ(mesh.colors[0], glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST(IndexedFaceSet, needsACoordinate3Before) {
    const auto root = sg::Separator::create();
    const auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValue({0, 1, 2});
    root->addChild(faces);
    sg::BoundingBoxAction action;
    EXPECT_EQ(errorOf<DataError>([&] { action.apply(*root); }),
              "IndexedFaceSet: no Coordinate3 before it; its coordIndex has no points to index");
}

} // namespace
} // namespace texsplat::nodes
