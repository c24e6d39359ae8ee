#include "scenegraph/actions/Action.h"

#include "TestNodes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/detail/VisitCount.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace texsplat::sg {
namespace {

using test::TestCube;

class VisitAction;

// A node with a member for VisitAction, as `void ScalarSplat::collectFrame(FrameAction&)` is.
class VisitedCube : public Declare<VisitedCube, TestCube> {
public:
    static constexpr const char* kTypeName = "VisitedCube";
    void visit(VisitAction& action);
};

// An action defined outside the core, as FrameAction is: it records visits through
// per-type methods without any virtual on Node.
class VisitAction : public Action {
public:
    VisitAction() : Action(methods()) {}
    static MethodTable& methods() {
        static MethodTable table = [] {
            MethodTable initial;
            initial.add<&VisitedCube::visit>();
            initial.add(Group::classType(), [](Action& action, Node& node) {
                static_cast<VisitAction&>(action).visits.push_back("group");
                node.doAction(action);
            });
            return initial;
        }();
        return table;
    }
    std::vector<std::string> visits;
};

void VisitedCube::visit(VisitAction& action) {
    action.visits.push_back("cube " + size.valueText() + " depth " +
                            std::to_string(action.pathNodes().size()));
}

Group::Ptr chain(std::size_t depth) {
    Group::Ptr root = Group::create();
    for (std::size_t i = 1; i < depth; ++i) {
        Group::Ptr parent = Group::create();
        parent->addChild(root);
        root = parent;
    }
    return root;
}

TEST(Action, dispatchesThroughTheMethodTableWithInheritance) {
    Group::Ptr root = Group::create();
    Separator::Ptr separator = Separator::create();
    separator->addChild(VisitedCube::create());
    separator->addChild(TestCube::create());
    root->addChild(separator);
    VisitAction action;
    action.apply(*root);
    // Separator has no entry of its own: it uses Group's, which calls Separator::doAction.
    // TestCube has no entry and no Node entry exists: it falls back to doAction().
    EXPECT_EQ(action.visits, (std::vector<std::string>{"group", "group", "cube 2 depth 3"}));
    EXPECT_TRUE(action.pathNodes().empty());
}

TEST(Action, traversalDepthIsLimited) {
    Group::Ptr root = chain(Action::kMaxDepth + 10);
    root->setName("top");
    BoundingBoxAction action;
    try {
        action.apply(*root);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "scene graph is nested deeper than the limit of 4096 levels "
                                   "(reached at Group under Group(top))");
    }
    EXPECT_TRUE(action.pathNodes().empty());
    // The action stays usable.
    Group::Ptr small = chain(Action::kMaxDepth);
    small->addChild(TestCube::create());
    action.apply(*small);
    EXPECT_FALSE(action.boundingBox().isEmpty());
}

TEST(Action, aPathologicalChainFailsCleanly) {
    Group::Ptr root = chain(100000);
    BoundingBoxAction action;
    EXPECT_THROW(action.apply(*root), DataError);
}

// 0: an empty group; i: a group that holds group i-1 twice, so it takes 2^(i+1) - 1 visits.
Group::Ptr doublingDag(int levels) {
    Group::Ptr level = Group::create();
    level->setName("a0");
    for (int i = 1; i < levels; ++i) {
        Group::Ptr next = Group::create();
        next->setName("a" + std::to_string(i));
        next->addChild(level);
        next->addChild(level);
        level = next;
    }
    return level;
}

TEST(Action, anExponentialDagIsRefusedBeforeTraversing) {
    Group::Ptr root = Group::create();
    root->addChild(doublingDag(64));
    BoundingBoxAction action;
    try {
        action.apply(*root);
        FAIL() << "no error";
    } catch (const DataError& error) {
        // a22 takes 8388607 visits, a23 the first more than 10^7.
        EXPECT_STREQ(error.what(),
                     "scene graph is too large to traverse: Group(a23) and the nodes under it "
                     "would be visited 16777215 times (a node shared with DEF/USE is visited "
                     "once per use), more than the limit of 10000000 (in the graph under Group)");
    }
    EXPECT_TRUE(action.pathNodes().empty());
    // Within the limit, shared nodes are traversed once per use, as counted.
    VisitAction visits;
    visits.apply(*doublingDag(10));
    EXPECT_EQ(visits.visits.size(), 1023u);
    const detail::VisitCount largest = detail::countVisits(*doublingDag(23), Action::kMaxVisits);
    EXPECT_EQ(largest.visits, (std::uint64_t{1} << 23) - 1);
    EXPECT_EQ(largest.overLimit, nullptr);
}

TEST(Action, anExponentialDagReadFromAFileIsRefused) {
    std::string text = "#Inventor V2.1 ascii\nDEF a0 Group { }\n";
    for (int i = 1; i < 64; ++i) {
        text += "DEF a" + std::to_string(i) + " Group { USE a" + std::to_string(i - 1) +
                " USE a" + std::to_string(i - 1) + " }\n";
    }
    text += "USE a63\n";
    const Node::Ptr root = SceneReader::readString(text, "dag.iv");
    BoundingBoxAction action;
    try {
        action.apply(*root);
        FAIL() << "no error";
    } catch (const DataError& error) {
        // Located at the node that multiplies the visits (it named no file or line).
        EXPECT_STREQ(error.what(),
                     "dag.iv:25:9: scene graph is too large to traverse: Group(a23) and the "
                     "nodes under it would be visited 16777215 times (a node shared with DEF/USE "
                     "is visited once per use), more than the limit of 10000000 (in the graph "
                     "under Separator)");
    }
}

TEST(Action, theWriterIsNotBoundByTheVisitLimit) {
    Group::Ptr root = doublingDag(64);
    // Each level is written once (DEF) and used once more (USE): 64 levels, about 20 KB.
    const std::string text = WriteAction::writeString(*root);
    EXPECT_NE(text.find("DEF a63 Group {"), std::string::npos);
    EXPECT_NE(text.find("USE a62"), std::string::npos);
    EXPECT_LT(text.size(), 30000u);
}

TEST(Action, terminationStopsGroups) {
    Group::Ptr root = Group::create();
    root->addChild(VisitedCube::create());
    root->addChild(VisitedCube::create());
    VisitAction action;
    action.setTerminated();
    action.apply(*root);
    // apply() clears an earlier termination: both cubes are visited.
    EXPECT_EQ(action.visits.size(), 3u);
    EXPECT_FALSE(action.hasTerminated());
}

} // namespace
} // namespace texsplat::sg
