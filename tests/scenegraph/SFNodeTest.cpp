#include "scenegraph/fields/SFNode.h"

#include "FakeValueReader.h"
#include "TestNodes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

class Holder : public Declare<Holder, Node> {
public:
    static constexpr const char* kTypeName = "Holder";
    SFNode target;

protected:
    Holder() { addField(target, "target", nullptr, "The node held"); }
};

TEST(SFNode, holdsASharedNodeAndBecomesItsParent) {
    Holder::Ptr holder = Holder::create();
    EXPECT_EQ(holder->target.typeName(), "SFNode");
    EXPECT_TRUE(holder->target.isDefault());
    EXPECT_EQ(holder->target.valueText(), "NULL");
    test::TestCube::Ptr cube = test::TestCube::create();
    holder->target = cube;
    EXPECT_EQ(holder->target.value(), cube);
    EXPECT_EQ(holder->target.valueText(), "TestCube");
    ASSERT_EQ(cube->parents().size(), 1u);
    EXPECT_EQ(cube->parents()[0], holder.get());
    holder->target = nullptr;
    EXPECT_TRUE(cube->parents().empty());
}

TEST(SFNode, changesOfTheReferencedNodeNotifyTheHolder) {
    Holder::Ptr holder = Holder::create();
    test::TestCube::Ptr cube = test::TestCube::create();
    holder->target = cube;
    test::RecordingObserver observer;
    holder->addObserver(observer);
    cube->size = 3.0f;
    ASSERT_EQ(observer.sources.size(), 1u);
    EXPECT_EQ(observer.sources[0], &cube->size);
    holder->removeObserver(observer);
}

TEST(SFNode, readsNullAndUse) {
    Holder::Ptr holder = Holder::create();
    test::TestCube::Ptr cube = test::TestCube::create();
    test::FakeValueReader use("USE box", {{"box", cube}});
    holder->target.readValue(use);
    EXPECT_EQ(holder->target.value(), cube);
    test::FakeValueReader null("NULL");
    holder->target.readValue(null);
    EXPECT_EQ(holder->target.value(), nullptr);
}

TEST(SFNode, referencingAnAncestorIsRejected) {
    Group::Ptr root = Group::create();
    root->setName("root");
    Holder::Ptr holder = Holder::create();
    root->addChild(holder);
    try {
        holder->target = root;
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "cannot make Group(root) the value of SFNode Holder.target: "
                                   "the scene graph would contain a cycle");
    }
    EXPECT_EQ(holder->target.value(), nullptr);
}

TEST(SFNode, destroyingTheHolderUnlinksTheNode) {
    test::TestCube::Ptr cube = test::TestCube::create();
    {
        Holder::Ptr holder = Holder::create();
        holder->target = cube;
    }
    EXPECT_TRUE(cube->parents().empty());
}

} // namespace
} // namespace texsplat::sg
