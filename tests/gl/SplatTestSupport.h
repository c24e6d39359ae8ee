#pragma once

#include "GlTestSupport.h"
#include "nodes/NodeTypes.h"
#include "nodes/image/Image.h"
#include "nodes/volume/Grid.h"
#include "nodes/volume/RawVolume.h"
#include "nodes/render/RenderedImage.h"
#include "nodes/render/SplatBatch.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "scenegraph/Declare.h"
#include "scenegraph/Group.h"
#include "scenegraph/Node.h"
#include "scenegraph/actions/RenderAction.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace texsplat::test {

/// @brief A test node that hands RenderAction one prepared splat batch or opaque draw, so the
/// splat drawing is tested through the action's real passes without the scene nodes.
class DrawNode : public sg::Declare<DrawNode, sg::Node> {
public:
    static constexpr const char* kTypeName = "TestDrawNode";

    /// @brief What render() queues: into the opaque pass or the splat pass.
    bool isOpaque = false;
    std::function<void()> draw;

    void render(sg::RenderAction& action) {
        if (isOpaque) {
            action.addOpaque(draw);
        } else {
            action.addSplats(draw);
        }
    }

    /// @brief Registers render() with the action (idempotent).
    static void registerMethod() { sg::RenderAction::methods().add<&DrawNode::render>(); }
};

/// @brief A node drawing `batch` seen through `view` in the splat pass.
inline DrawNode::Ptr splatNode(render::SplatBatch& batch, const render::SplatView& view) {
    DrawNode::registerMethod();
    DrawNode::Ptr node = DrawNode::create();
    node->draw = [&batch, view] { batch.draw(view); };
    return node;
}

/// @brief A node drawing `draw` in the opaque pass.
inline DrawNode::Ptr opaqueNode(std::function<void()> draw) {
    DrawNode::registerMethod();
    DrawNode::Ptr node = DrawNode::create();
    node->isOpaque = true;
    node->draw = std::move(draw);
    return node;
}

/// @brief Renders the nodes under a group with a fresh action and reads the image back.
inline image::Image renderNodes(int width, int height, const std::vector<sg::Node::Ptr>& nodes) {
    sg::Group::Ptr root = sg::Group::create();
    for (const sg::Node::Ptr& node : nodes) {
        root->addChild(node);
    }
    sg::RenderAction action(width, height);
    action.render(*root);
    return render::renderedImage(action, render::DepthReadback::With);
}

/// @brief An orthographic camera looking down −z at the square [x0, x0 + size]² in the plane
/// z = 0, from z = 10.
inline render::SplatView topView(float x0, float size, const glm::vec3& spacing = glm::vec3(1.0f)) {
    const glm::mat4 view =
        glm::lookAt(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 projection = glm::ortho(x0, x0 + size, x0, x0 + size, 1.0f, 20.0f);
    return render::SplatView::fromMatrices(glm::mat4(1.0f), view, projection, spacing);
}

/// @brief Writes `grid` as a raw file in the test's temporary folder and answers its path.
inline std::string writeTestVolume(const std::string& name, const volume::ScalarGrid& grid) {
    const std::string path = ::testing::TempDir() + "texsplat_render_" + name + ".raw";
    volume::writeRawVolume(path, grid);
    return path;
}

/// @brief Renders `root` with a new action and reads color and depth back.
inline image::Image renderScene(sg::Node& root, int width, int height) {
    nodes::registerNodeTypes();
    sg::RenderAction action(width, height);
    action.render(root);
    return render::renderedImage(action, render::DepthReadback::With);
}

/// @brief Whether every pixel is finite and at least one has color.
inline void expectFiniteAndNotEmpty(const image::Image& image, const std::string& what) {
    const image::Image::Statistics statistics = image.statistics();
    EXPECT_EQ(statistics.nonFinitePixels, 0u) << what;
    EXPECT_GT(statistics.maximum.r + statistics.maximum.g + statistics.maximum.b, 0.0) << what;
}

} // namespace texsplat::test
