#include "scenegraph/Node.h"

#include "TestNodes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/Separator.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

using test::RecordingObserver;
using test::TestCube;

TEST(Node, typeNameAndHierarchy) {
    TestCube::Ptr cube = TestCube::create();
    EXPECT_EQ(cube->typeName(), "TestCube");
    EXPECT_EQ(&cube->type(), &TestCube::classType());
    EXPECT_TRUE(cube->type().isDerivedFrom(Node::classType()));
    EXPECT_TRUE(cube->type().isDerivedFrom(FieldContainer::classType()));
    EXPECT_FALSE(cube->type().isDerivedFrom(Group::classType()));
    EXPECT_TRUE(Separator::classType().isDerivedFrom(Group::classType()));
    EXPECT_TRUE(Node::classType().isAbstract());
    EXPECT_FALSE(TestCube::classType().isAbstract());
    EXPECT_EQ(cube->asNode(), cube.get());
    EXPECT_EQ(cube->sharedNode(), cube);
}

TEST(Node, fieldsAreListedInDeclarationOrderWithDefaults) {
    TestCube::Ptr cube = TestCube::create();
    ASSERT_EQ(cube->fields().size(), 1u);
    EXPECT_EQ(cube->fields()[0], &cube->size);
    EXPECT_EQ(cube->size.value(), 2.0f);
    EXPECT_TRUE(cube->size.isDefault());
}

TEST(Node, namesFollowInventorRules) {
    TestCube::Ptr cube = TestCube::create();
    cube->setName("box_1-a");
    EXPECT_EQ(cube->name(), "box_1-a");
    EXPECT_EQ(cube->describe(), "TestCube(box_1-a)");
    cube->setName("");
    EXPECT_EQ(cube->describe(), "TestCube");
    try {
        cube->setName("1box");
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "TestCube: invalid name '1box' (a name must not start with a "
                                   "digit or '#' and must not contain whitespace, control "
                                   "characters or any of \"'+,.[\\]{})");
    }
    try {
        cube->setName("_");
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "TestCube: invalid name '_' (it is reserved: Inventor writers "
                                   "name a node that has no name '_+N')");
    }
    // Exactly the names the scene reader cannot read back (WriteActionTest reads the others).
    for (const char* name : {"a b", "a\tb", "a\nb", "a\x01", "a\x7f", "#a", "a\"b", "a'b", "a+1",
                             "a,b", "a.b", "part[1]", "a]", "a\\b", "a{", "a}"}) {
        SCOPED_TRACE(name);
        EXPECT_THROW(cube->setName(name), DataError);
    }
    EXPECT_EQ(cube->name(), "");
}

TEST(Node, changesNotifyEveryAncestorOnce) {
    // A diamond: root -> left, right -> shared cube.
    Group::Ptr root = Group::create();
    Group::Ptr left = Group::create();
    Group::Ptr right = Group::create();
    TestCube::Ptr cube = TestCube::create();
    root->addChild(left);
    root->addChild(right);
    left->addChild(cube);
    right->addChild(cube);
    RecordingObserver rootObserver;
    RecordingObserver leftObserver;
    root->addObserver(rootObserver);
    left->addObserver(leftObserver);
    cube->size = 9.0f;
    ASSERT_EQ(rootObserver.subjects.size(), 1u);
    EXPECT_EQ(rootObserver.subjects[0], root.get());
    EXPECT_EQ(rootObserver.sources[0], &cube->size);
    EXPECT_EQ(leftObserver.subjects.size(), 1u);
    cube->touch();
    EXPECT_EQ(rootObserver.subjects.size(), 2u);
    EXPECT_EQ(rootObserver.sources[1], nullptr);
    root->removeObserver(rootObserver);
    left->removeObserver(leftObserver);
}

TEST(Node, hasAncestorFollowsEveryParent) {
    Group::Ptr root = Group::create();
    Group::Ptr middle = Group::create();
    TestCube::Ptr cube = TestCube::create();
    root->addChild(middle);
    middle->addChild(cube);
    EXPECT_TRUE(cube->hasAncestor(*root));
    EXPECT_TRUE(cube->hasAncestor(*cube));
    EXPECT_FALSE(root->hasAncestor(*cube));
}

TEST(Node, cannotBeCreatedWhenAbstract) {
    try {
        Node::classType().create();
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "cannot create a Node: it is an abstract type");
    }
}

} // namespace
} // namespace texsplat::sg
