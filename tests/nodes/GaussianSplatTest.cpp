#include "nodes/GaussianSplat.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/RayCastAction.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <string>

namespace texsplat::nodes {
namespace {

// The fields are checked before anything is loaded or drawn, so no volume is needed. Messages
// start with where the node was read: line 2, column 19 of the scene text.
std::string errorOfDrawing(const std::string& fields) {
    registerNodeTypes();
    const sg::Node::Ptr root = sg::SceneReader::readString(
        "#Inventor V2.1 ascii\nSeparator { DEF g GaussianSplat { " + fields + " } }");
    return test::errorOf<DataError>([&] { sg::RayCastAction(4, 4).render(*root); });
}

TEST(GaussianSplat, boundsTheVerticesOfItsFan) {
    EXPECT_EQ(errorOfDrawing("radialSamples 100000 azimuthSamples 100000"),
              "<string>:2:19: GaussianSplat 'g': radialSamples must be 2 to 64, got 100000");
    EXPECT_EQ(errorOfDrawing("radialSamples 1"),
              "<string>:2:19: GaussianSplat 'g': radialSamples must be 2 to 64, got 1");
    EXPECT_EQ(errorOfDrawing("azimuthSamples 257"),
              "<string>:2:19: GaussianSplat 'g': azimuthSamples must be 3 to 256, got 257");
    EXPECT_EQ(errorOfDrawing("azimuthSamples -3"),
              "<string>:2:19: GaussianSplat 'g': azimuthSamples must be 3 to 256, got -3");
    // ScalarSplat's own checks come first.
    EXPECT_EQ(errorOfDrawing("size -1 radialSamples 100000"),
              "<string>:2:19: GaussianSplat 'g': size must be finite and > 0, got -1");
    // Within the bounds the check passes and drawing goes on to find its volume.
    EXPECT_EQ(errorOfDrawing("radialSamples 64 azimuthSamples 256"),
              "<string>:2:19: GaussianSplat 'g': no VolumeData before this node");
}

} // namespace
} // namespace texsplat::nodes
