#include "scenegraph/io/UnknownNode.h"

#include "SceneTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"

#include <gtest/gtest.h>

using namespace texsplat::sg;
using namespace texsplat::sg::test;

namespace {

const std::string kForeign = R"(#Inventor V2.1 ascii

DEF foreign ForeignNode {
    fields [ SFEnum mode, MFVec2f points, SFNode child, MFRotation turns, SFString note,
        SFFloat unset ]
    mode WEIRD
    points [ 1 2, 3 4 ]
    child Other {
        fields [ ]
    }
    turns 0 0 1 0.5
    note "pass me through"
    Group {
    }
}
)";

TEST(UnknownNode, readsAnUndeclaredTypeFromItsDescriptionAndWritesItBackIdentically) {
    const Node::Ptr root = SceneReader::readString(kForeign);
    EXPECT_EQ(root->typeName(), "ForeignNode");
    EXPECT_TRUE(root->type().isDerivedFrom(UnknownNode::classType()));
    EXPECT_EQ(root->name(), "foreign");
    ASSERT_EQ(root->fields().size(), 6u);
    EXPECT_EQ(root->findField("points")->typeName(), "MFVec2f");
    EXPECT_EQ(root->findField("points")->valueText(), "[ 1 2, 3 4 ]");
    EXPECT_EQ(root->findField("mode")->valueText(), "WEIRD");
    EXPECT_EQ(root->findField("child")->valueText(), "Other");
    EXPECT_TRUE(root->findField("unset")->isDefault());
    EXPECT_EQ(static_cast<const Group&>(*root).childCount(), 1u);
    EXPECT_EQ(WriteAction::writeString(*root), kForeign);
}

TEST(UnknownNode, isFoundBySearchingForItsCommonType) {
    const Node::Ptr root = SceneReader::readString(
        "#Inventor V2.1 ascii\nSeparator { A { fields [ ] } Group { B { fields [ ] } } }");
    SearchAction search;
    search.setType(UnknownNode::classType());
    search.setInterest(SearchAction::Interest::All);
    search.apply(*root);
    ASSERT_EQ(search.paths().size(), 2u);
    EXPECT_EQ(search.paths()[1].tail()->typeName(), "B");
}

TEST(UnknownNode, rejectsUnsupportedTypesAndRepeatedNames) {
    const UnknownNode::Ptr node = UnknownNode::create("Foreign");
    node->addDescribedField("SFFloat", "size");
    try {
        node->addDescribedField("SFImage", "picture");
        FAIL() << "no error";
    } catch (const texsplat::DataError& error) {
        EXPECT_STREQ(error.what(), "Foreign: unsupported field type 'SFImage' for field 'picture'");
    }
    try {
        node->addDescribedField("SFInt32", "size");
        FAIL() << "no error";
    } catch (const texsplat::DataError& error) {
        EXPECT_STREQ(error.what(), "Foreign: field 'size' is described twice");
    }
    EXPECT_TRUE(UnknownNode::isDescribableFieldType("MFMatrix"));
    EXPECT_FALSE(UnknownNode::isDescribableFieldType("SFImage"));
}

TEST(UnknownNode, keepsTheLastEnumValueItWasGiven) {
    const UnknownNode::Ptr node = UnknownNode::create("Foreign");
    auto& mode = static_cast<SFEnum&>(node->addDescribedField("SFEnum", "mode"));
    node->setEnumValue(mode, "FIRST");
    node->setEnumValue(mode, "SECOND");
    EXPECT_EQ(mode.valueText(), "SECOND");
    EXPECT_FALSE(mode.isDefault());
}

} // namespace
