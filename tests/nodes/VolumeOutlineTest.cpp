// The volume outline drawn into rendered images: boxes of the splat nodes' volumes through the
// camera that renders them, clipped to the view.

#include "nodes/annotation/VolumeOutline.h"

#include "nodes/NodeTypes.h"
#include "scenegraph/io/SceneReader.h"

#include <glm/common.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace texsplat::annotation {
namespace {

sg::Node::Ptr sceneWith(const std::string& camera, const std::string& splats) {
    nodes::registerNodeTypes();
    return sg::SceneReader::readString("#Inventor V2.1 ascii\nSeparator {\n" + camera +
                                           "\nTransferFunction { }\n"
                                           "VolumeData { source BLOB resolution 8 8 8 }\n" +
                                           splats + "\n}\n",
                                       "outline.iv");
}

TEST(VolumeOutline, aBoxInViewHasTwelveEdgesInsideTheImage) {
    const sg::Node::Ptr scene =
        sceneWith("PerspectiveCamera { position 0 0 10 nearDistance 1 farDistance 100 }",
                  "TextureSplat { }");
    const VolumeOutline outline = VolumeOutline::ofScene(*scene, 200, 100, glm::vec4(1.0f));
    ASSERT_EQ(outline.segments().size(), 12u);
    for (const VolumeOutline::Segment& segment : outline.segments()) {
        for (const glm::vec2 end : {segment.from, segment.to}) {
            EXPECT_GT(end.x, 0.0f);
            EXPECT_LT(end.x, 200.0f);
            EXPECT_GT(end.y, 0.0f);
            EXPECT_LT(end.y, 100.0f);
        }
    }
    image::Image image(200, 100);
    outline.draw(image);
    const glm::ivec2 corner(glm::floor(outline.segments().front().from));
    EXPECT_EQ(image.pixel(corner.x, corner.y), glm::vec4(1.0f));
}

TEST(VolumeOutline, edgesAreClippedToTheViewFromInsideTheVolume) {
    const sg::Node::Ptr scene =
        sceneWith("PerspectiveCamera { position 0 0 0 heightAngle 2.5 nearDistance 0.01 "
                  "farDistance 100 }",
                  "TextureSplat { }");
    const VolumeOutline outline = VolumeOutline::ofScene(*scene, 64, 64, glm::vec4(1.0f));
    // A wide view from the centre: the far face's four edges, and the part in front of the eye
    // of the four edges along the view; the near face is behind the eye. None leaves the image.
    EXPECT_EQ(outline.segments().size(), 8u);
    for (const VolumeOutline::Segment& segment : outline.segments()) {
        for (const glm::vec2 end : {segment.from, segment.to}) {
            EXPECT_TRUE(std::isfinite(end.x) && std::isfinite(end.y));
            EXPECT_GE(end.x, -1e-3f);
            EXPECT_LE(end.x, 64.0f + 1e-3f);
            EXPECT_GE(end.y, -1e-3f);
            EXPECT_LE(end.y, 64.0f + 1e-3f);
        }
    }
}

TEST(VolumeOutline, edgesOfFacesTurnedAwayLieBehindTheVolume) {
    // Seen from a corner's side: three faces face the eye, three do not; the three edges where
    // two of the far faces meet lie behind the volume.
    for (const std::string camera :
         {"PerspectiveCamera { position 3 4 10 orientation -0.8 0.6 0 0.45 nearDistance 1 "
          "farDistance 100 }",
          "OrthographicCamera { position 3 4 10 orientation -0.8 0.6 0 0.45 nearDistance 1 "
          "farDistance 100 height 4 }"}) {
        const sg::Node::Ptr scene = sceneWith(camera, "TextureSplat { }");
        const VolumeOutline outline = VolumeOutline::ofScene(*scene, 128, 128, glm::vec4(1.0f));
        ASSERT_EQ(outline.segments().size(), 12u) << camera;
        int behind = 0;
        for (const VolumeOutline::Segment& segment : outline.segments()) {
            behind += segment.isBehind ? 1 : 0;
        }
        EXPECT_EQ(behind, 3) << camera;
        image::Image front(128, 128);
        outline.draw(front, VolumeOutline::Edges::InFront);
        image::Image back(128, 128);
        outline.draw(back, VolumeOutline::Edges::Behind);
        image::Image all(128, 128);
        outline.draw(all);
        int frontPixels = 0;
        int backPixels = 0;
        int allPixels = 0;
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) {
                frontPixels += front.pixel(x, y).a > 0.0f ? 1 : 0;
                backPixels += back.pixel(x, y).a > 0.0f ? 1 : 0;
                allPixels += all.pixel(x, y).a > 0.0f ? 1 : 0;
            }
        EXPECT_GT(backPixels, 20);
        EXPECT_GT(frontPixels, 2 * backPixels);
        EXPECT_LE(allPixels, frontPixels + backPixels);
    }
}

TEST(VolumeOutline, aSceneWithoutSplatNodesHasNone) {
    const sg::Node::Ptr scene = sceneWith("PerspectiveCamera { position 0 0 10 }", "");
    EXPECT_TRUE(VolumeOutline::ofScene(*scene, 64, 64, glm::vec4(1.0f)).segments().empty());
}

} // namespace
} // namespace texsplat::annotation
