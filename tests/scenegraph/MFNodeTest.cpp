#include "scenegraph/fields/MFNode.h"

#include "FakeValueReader.h"
#include "TestNodes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

class Layers : public Declare<Layers, Node> {
public:
    static constexpr const char* kTypeName = "Layers";
    MFNode layers;

protected:
    Layers() { addField(layers, "layers", std::vector<Node::Ptr>{}, "Nodes drawn in order"); }
};

TEST(MFNode, holdsNodesAndKeepsParentsInStep) {
    Layers::Ptr holder = Layers::create();
    EXPECT_EQ(holder->layers.typeName(), "MFNode");
    test::TestCube::Ptr a = test::TestCube::create();
    test::TestCube::Ptr b = test::TestCube::create();
    holder->layers.setValue({a, b, a});
    EXPECT_EQ(holder->layers.size(), 3u);
    EXPECT_EQ(a->parents().size(), 2u);
    EXPECT_EQ(holder->layers.valueText(), "[ TestCube, TestCube, TestCube ]");
    holder->layers.set1Value(0, b);
    EXPECT_EQ(a->parents().size(), 1u);
    EXPECT_EQ(b->parents().size(), 2u);
    holder->layers.set1Value(4, nullptr);
    EXPECT_EQ(holder->layers.size(), 5u);
    holder->layers.setValue({});
    EXPECT_TRUE(a->parents().empty());
    EXPECT_TRUE(b->parents().empty());
}

TEST(MFNode, readsListsOfUseAndNull) {
    Layers::Ptr holder = Layers::create();
    test::TestCube::Ptr cube = test::TestCube::create();
    test::FakeValueReader reader("[ USE c, NULL, USE c ]", {{"c", cube}});
    holder->layers.readValue(reader);
    ASSERT_EQ(holder->layers.size(), 3u);
    EXPECT_EQ(holder->layers[0], cube);
    EXPECT_EQ(holder->layers[1], nullptr);
    EXPECT_EQ(cube->parents().size(), 2u);
}

TEST(MFNode, aCycleLeavesTheFieldUnchanged) {
    Group::Ptr root = Group::create();
    Layers::Ptr holder = Layers::create();
    root->addChild(holder);
    test::TestCube::Ptr cube = test::TestCube::create();
    holder->layers.setValue({cube});
    try {
        holder->layers.setValue({cube, root});
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "cannot make Group a value of MFNode Layers.layers: "
                                   "the scene graph would contain a cycle");
    }
    EXPECT_EQ(holder->layers.size(), 1u);
    EXPECT_EQ(cube->parents().size(), 1u);
    EXPECT_EQ(root->parents().size(), 0u);
}

} // namespace
} // namespace texsplat::sg
