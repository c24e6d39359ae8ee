// `texsplat render --outline`: the 12 edges of the volume's box, projected with the scene's
// camera, drawn into the image by either backend and the reference: the edges that face the
// camera over the volume, the three behind it under it.

#include "RunCommand.h"

#include "nodes/VolumeData.h"
#include "nodes/image/ImageIo.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace texsplat {
namespace {

using test::runTexsplat;

constexpr int kWidth = 160;
constexpr int kHeight = 120;
constexpr float kAngle = 0.5f; // of the Transform, about (1, 1, 0)

class OutlineCommandTest : public test::ScratchDirectoryTest {
protected:
    // A blob volume turned by a Transform, seen by an orthographic camera on the +z axis whose
    // view is 1.5 times the box's diagonal high; `opacities` the transfer function's.
    std::string writeScene(const std::string& opacities = "[ 0, 2 ]") {
        const auto volume = nodes::VolumeData::create();
        volume->resolution.setValue(glm::vec3(12.0f));
        mBox = volume->bounds();
        mViewHeight = 1.5f * glm::length(mBox.max() - mBox.min());
        return write("blob.iv",
                     "#Inventor V2.1 ascii\nSeparator {\n"
                     "OrthographicCamera { position 0 0 50 nearDistance 1 farDistance 100 "
                     "height " + std::to_string(mViewHeight) + " }\n"
                     "TransferFunction { opacities " + opacities + " }\n"
                     "Transform { rotation 0.70710678 0.70710678 0 " + std::to_string(kAngle) +
                         " }\n"
                     "VolumeData { source BLOB resolution 12 12 12 }\n"
                     "TextureSplat { }\n}\n");
    }

    // The box's corners in pixels, projected by hand: the rotation, then the orthographic view
    // (camera space is world space moved by the camera position; ndc = xy / half the view).
    std::vector<glm::vec2> projectedCorners() const {
        const glm::mat4 rotation =
            glm::rotate(glm::mat4(1.0f), kAngle, glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)));
        const float halfHeight = 0.5f * mViewHeight;
        const float halfWidth = halfHeight * float(kWidth) / float(kHeight);
        std::vector<glm::vec2> corners;
        float farthest = 0.0f;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 world(rotation * glm::vec4(mBox.corner(corner), 1.0f));
            corners.emplace_back((world.x / halfWidth + 1.0f) * 0.5f * kWidth,
                                 (1.0f - world.y / halfHeight) * 0.5f * kHeight);
            // The camera looks along -z: the hidden corner is the lowest one.
            if (corner == 0 || world.z < farthest) {
                farthest = world.z;
                mHiddenCorner = corner;
            }
        }
        return corners;
    }

    sg::Box3 mBox;
    float mViewHeight = 0.0f;
    // Set by projectedCorners(): where the three faces turned away from the camera meet.
    mutable std::size_t mHiddenCorner = 0;
};

// Whether a pixel within one of `at` is green, the outline colour of the test.
bool greenNear(const image::Image& image, glm::vec2 at) {
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const glm::ivec2 pixel = glm::ivec2(glm::floor(at)) + glm::ivec2(dx, dy);
            if (pixel.x >= 0 && pixel.y >= 0 && pixel.x < image.width() &&
                pixel.y < image.height() &&
                image.pixel(pixel.x, pixel.y) == glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)) {
                return true;
            }
        }
    }
    return false;
}

TEST_F(OutlineCommandTest, theBoxCornersAreDrawnWithTheScenesCameraInEveryBackend) {
    const std::string scene = writeScene();
    const std::vector<glm::vec2> corners = projectedCorners();
    for (const std::string how : {"--backend cpu", "--backend gl", "--raycast"}) {
        const std::string output = path("outline.png");
        const std::string size = " --size " + std::to_string(kWidth) + "x" +
                                 std::to_string(kHeight) + " " + how;
        const auto plain = runTexsplat("render " + scene + " -o " + output + size);
        ASSERT_EQ(plain.exitCode, 0) << how << ": " << plain.standardError;
        const image::Image without = image::readImage(output);
        const auto outlined = runTexsplat("render " + scene + " -o " + output + size +
                                          " --outline --outline-color 0,1,0");
        ASSERT_EQ(outlined.exitCode, 0) << how << ": " << outlined.standardError;
        const image::Image with = image::readImage(output);
        for (std::size_t corner = 0; corner < corners.size(); ++corner) {
            ASSERT_GT(corners[corner].x, 1.0f);
            ASSERT_LT(corners[corner].x, kWidth - 1.0f);
            EXPECT_EQ(greenNear(with, corners[corner]), corner != mHiddenCorner)
                << how << " corner " << corner << " at " << corners[corner].x << ", "
                << corners[corner].y << ": green over the volume unless hidden";
            EXPECT_FALSE(greenNear(without, corners[corner])) << how << " corner " << corner;
        }
        // The hidden corner's edges lie under the volume: green added where it lets light
        // through, (1 − α) times the line, red and blue as without them.
        const glm::ivec2 hidden(glm::floor(corners[mHiddenCorner]));
        const glm::vec4 under = with.pixel(hidden.x, hidden.y);
        const glm::vec4 alone = without.pixel(hidden.x, hidden.y);
        EXPECT_NEAR(under.r, alone.r, 1.0f / 255.0f) << how;
        EXPECT_NEAR(under.b, alone.b, 1.0f / 255.0f) << how;
        EXPECT_GT(under.g, alone.g + 0.1f) << how << ": the blob is thin at its box's corners";
    }
}

TEST_F(OutlineCommandTest, anOpaqueVolumeHidesTheEdgesBehindIt) {
    // Every voxel opaque: the box is a solid whose silhouette holds the hidden corner.
    const std::string scene = writeScene("[ 50, 50 ]");
    const std::vector<glm::vec2> corners = projectedCorners();
    const std::string output = path("opaque.png");
    const std::string size =
        " --size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --backend cpu";
    ASSERT_EQ(runTexsplat("render " + scene + " -o " + output + size).exitCode, 0);
    const image::Image without = image::readImage(output);
    ASSERT_EQ(runTexsplat("render " + scene + " -o " + output + size +
                          " --outline --outline-color 0,1,0")
                  .exitCode,
              0);
    const image::Image with = image::readImage(output);
    const glm::ivec2 hidden(glm::floor(corners[mHiddenCorner]));
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            EXPECT_EQ(with.pixel(hidden.x + dx, hidden.y + dy),
                      without.pixel(hidden.x + dx, hidden.y + dy))
                << "the hidden corner's edges do not show through an opaque volume";
        }
    for (std::size_t corner = 0; corner < corners.size(); ++corner) {
        if (corner != mHiddenCorner) {
            EXPECT_TRUE(greenNear(with, corners[corner])) << "corner " << corner;
        }
    }
}

TEST_F(OutlineCommandTest, badUsesAreNamed) {
    const std::string scene = writeScene();
    const std::string output = path("outline.png");
    const auto color =
        runTexsplat("render " + scene + " -o " + output + " --outline --outline-color red");
    EXPECT_EQ(color.exitCode, 1);
    EXPECT_EQ(color.standardError, "texsplat: error: --outline-color: expected black, white or "
                                   "r,g,b (0 to 1), got 'red'\n");
    const auto alone = runTexsplat("render " + scene + " -o " + output + " --outline-color 1,0,0");
    EXPECT_EQ(alone.exitCode, 2); // a usage error, CLI11's
    const std::string expected = "texsplat: error: --outline-color requires --outline\n";
    EXPECT_EQ(alone.standardError.substr(0, expected.size()), expected);
}

} // namespace
} // namespace texsplat
