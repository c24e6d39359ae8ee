#include "scenegraph/actions/Action.h"

#include "TestNodes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace texsplat::sg {
namespace {

using test::TestCube;

class VisitAction;

// A node with a member for VisitAction, as `void TextureSplat::render(RenderAction&)` will be.
class VisitedCube : public Declare<VisitedCube, TestCube> {
public:
    static constexpr const char* kTypeName = "VisitedCube";
    void visit(VisitAction& action);
};

// An action defined outside the core, as RenderAction will be: it records visits through
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
