// What a GL frame holds, read from its memory counters (sg::FrameMemory in RenderStatistics,
// printed by `texsplat render --time-report`): a scene pays only for what it uses (issue 13) —
// the footprint texture with texture splats, the mark table only with vector splats, and
// neither grids, classified voxels, splats nor textures for a scene of meshes alone.
#include "SplatTestSupport.h"

#include "nodes/CombinedSplat.h"
#include "nodes/Coordinate3.h"
#include "nodes/IndexedFaceSet.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/VectorSplat.h"

#include <gtest/gtest.h>

namespace texsplat::nodes {
namespace {

sg::FrameMemory glFrameMemory(const std::vector<sg::Node::Ptr>& nodes) {
    test::sharedContext();
    registerNodeTypes();
    const sg::Separator::Ptr root = test::framedScene(PerspectiveCamera::create(), nodes);
    return test::renderFrame(*root, 48, 48).statistics.memory;
}

VolumeData::Ptr tornado() {
    VolumeData::Ptr volume = VolumeData::create();
    volume->source.setValue(VolumeSource::Tornado);
    volume->resolution.setValue(glm::vec3(12.0f));
    return volume;
}

TransferFunction::Ptr glow() {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 0.32f));
    transfer->opacities.setValue({0.0f, 30.0f});
    return transfer;
}

TEST(GlFrameMemory, aFrameHoldsOnlyTheTexturesItsSplatsUse) {
    const sg::FrameMemory scalar = glFrameMemory({tornado(), glow(), TextureSplat::create()});
    EXPECT_GT(scalar.grids, 0u);
    EXPECT_GT(scalar.classified, 0u);
    EXPECT_GT(scalar.splats, 0u);
    EXPECT_GT(scalar.textures, 0u); // the footprint
    // Marks are drawn from their shape, without a texture; combined splats use the footprint's.
    const sg::FrameMemory vector = glFrameMemory({tornado(), glow(), VectorSplat::create()});
    EXPECT_EQ(vector.textures, 0u);
    const sg::FrameMemory combined = glFrameMemory({tornado(), glow(), CombinedSplat::create()});
    EXPECT_EQ(combined.textures, scalar.textures);

    Coordinate3::Ptr corners = Coordinate3::create();
    corners->point.setValue({glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f),
                             glm::vec3(1.0f, 1.0f, 0.0f)});
    IndexedFaceSet::Ptr triangle = IndexedFaceSet::create();
    triangle->coordIndex.setValue({0, 1, 2, -1});
    const sg::FrameMemory meshes = glFrameMemory({corners, triangle});
    EXPECT_EQ(meshes.grids, 0u);
    EXPECT_EQ(meshes.classified, 0u);
    EXPECT_EQ(meshes.octree, 0u);
    EXPECT_EQ(meshes.splats, 0u);
    EXPECT_EQ(meshes.textures, 0u);
}

} // namespace
} // namespace texsplat::nodes
