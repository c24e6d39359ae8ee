// Progress and cancel of a frame's long steps (issue 13): classification and the octree build
// report to the action's work progress, which may cancel them; a cancelled step is started again
// by the next frame.
#include "nodes/volume/SparseGrid.h"

#include "nodes/NodeTypes.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/Frame.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/SceneFraming.h"
#include "scenegraph/Separator.h"
#include "scenegraph/WorkProgress.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace texsplat::nodes {
namespace {

// A ball in a 48³ box, drawn with a budget so that a frame classifies and builds an octree.
sg::Node::Ptr ballScene() {
    auto grid = std::make_shared<volume::SparseScalarGrid>(volume::GridGeometry(glm::i64vec3(48)));
    for (std::int64_t z = 0; z < 48; ++z)
        for (std::int64_t y = 0; y < 48; ++y)
            for (std::int64_t x = 0; x < 48; ++x) {
                const double r = glm::length(glm::dvec3(x, y, z) - glm::dvec3(24.0)) / 20.0;
                if (r < 1.0) {
                    grid->setValue(glm::i64vec3(x, y, z), static_cast<float>(1.0 - r));
                }
            }
    auto data = VolumeData::create();
    data->setGrid(volume::ScalarGridPtr(grid));
    auto transfer = TransferFunction::create();
    transfer->rangeMode.setValue(RangeMode::Fixed);
    auto splat = TextureSplat::create();
    splat->maxSplats.setValue(500);
    auto root = sg::Separator::create();
    root->addChild(data);
    root->addChild(transfer);
    root->addChild(splat);
    return render::framedScene(root, 1.0f);
}

class WorkProgressTest : public ::testing::Test {
protected:
    void SetUp() override { registerNodeTypes(); }
};

TEST_F(WorkProgressTest, classificationAndTheOctreeBuildReportFromZeroToOne) {
    const sg::Node::Ptr scene = ballScene();
    std::vector<std::pair<std::string, double>> reports;
    render::FrameAction action(16, 16);
    action.setWorkProgress([&reports](std::string_view step, double fraction) {
        reports.emplace_back(std::string(step), fraction);
        return true;
    });
    action.collect(*scene);
    ASSERT_GE(reports.size(), 4u);
    EXPECT_EQ(reports.front(), std::make_pair(std::string("classifying"), 0.0));
    EXPECT_EQ(reports.back(), std::make_pair(std::string("building the octree"), 1.0));
    for (std::size_t i = 1; i < reports.size(); ++i) {
        if (reports[i].first == reports[i - 1].first) {
            EXPECT_GE(reports[i].second, reports[i - 1].second) << i;
        }
    }
    reports.clear();
    action.collect(*scene);
    EXPECT_TRUE(reports.empty()) << "a frame that makes nothing new reports nothing";
}

TEST_F(WorkProgressTest, aCancelledStepThrowsAndTheNextFrameStartsItAgain) {
    for (const std::string cancelled : {"classifying", "building the octree"}) {
        SCOPED_TRACE(cancelled);
        const sg::Node::Ptr scene = ballScene();
        render::FrameAction action(16, 16);
        action.setWorkProgress([&cancelled](std::string_view step, double) {
            return step != cancelled;
        });
        try {
            action.collect(*scene);
            ADD_FAILURE() << "not cancelled";
        } catch (const sg::Cancelled& error) {
            EXPECT_NE(std::string(error.what()).find("TextureSplat: " + cancelled + ": cancelled"),
                      std::string::npos)
                << error.what();
        }
        action.setWorkProgress({});
        const render::Frame& frame = action.collect(*scene);
        ASSERT_EQ(frame.splats.size(), 1u);
        EXPECT_GT(frame.splats.front().splats->size(), 400u);
        EXPECT_EQ(action.statistics().builds.octrees, 1u);
        // Cancelling the octree build keeps the classification it was building on.
        EXPECT_EQ(action.statistics().builds.classifications,
                  cancelled == "classifying" ? 1u : 0u);
    }
}

} // namespace
} // namespace texsplat::nodes
