#include "TestNodes.h"
#include "scenegraph/Error.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <string>

namespace texsplat::sg {
namespace {

// A cube that checks its size when it is used, as nodes check their fields after parsing.
class CheckedCube : public Declare<CheckedCube, test::TestCube> {
public:
    static constexpr const char* kTypeName = "CheckedCube";

    void getBoundingBox(BoundingBoxAction& action) override {
        if (size.value() <= 0.0f) {
            throw DataError("CheckedCube: size must be > 0, got " + size.valueText());
        }
        test::TestCube::getBoundingBox(action);
    }
};

std::string boundingBoxError(Node& root) {
    try {
        BoundingBoxAction().apply(root);
    } catch (const DataError& error) {
        return error.what();
    }
    return "no error";
}

Node::Ptr read(const std::string& text) {
    NodeRegistry::instance().add<CheckedCube>();
    return SceneReader::readString(text, "cubes.iv");
}

} // namespace

TEST(NodeLocation, theReaderRecordsWhereEachNodeWasRead) {
    const Node::Ptr root = read("#Inventor V2.1 ascii\nSeparator {\n  DEF c CheckedCube { }\n}\n");
    EXPECT_EQ(root->sourceLocation(), "cubes.iv:2:1");
    const auto& group = static_cast<const Group&>(*root);
    // A DEF'd node is where its type name is, as the parser's own messages point.
    EXPECT_EQ(group.child(0)->sourceLocation(), "cubes.iv:3:9");
    EXPECT_EQ(Separator::create()->sourceLocation(), "");
}

TEST(NodeLocation, anErrorRaisedAtANodeStartsWithWhereTheNodeWasRead) {
    const Node::Ptr root = read("#Inventor V2.1 ascii\nSeparator {\n  CheckedCube { }\n"
                                "  Separator {\n    CheckedCube { size -1 }\n  }\n}\n");
    // The innermost node claims the error; the Separators around it add nothing.
    EXPECT_EQ(boundingBoxError(*root), "cubes.iv:5:5: CheckedCube: size must be > 0, got -1");
}

TEST(NodeLocation, aNodeMadeInCodeIsNotBlamedOnTheFileAroundIt) {
    const Node::Ptr root = read("#Inventor V2.1 ascii\nSeparator { CheckedCube { } }\n");
    const auto cube = CheckedCube::create();
    cube->size.setValue(0.0f);
    static_cast<Group&>(*root).addChild(cube);
    EXPECT_EQ(boundingBoxError(*root), "CheckedCube: size must be > 0, got 0");
}

} // namespace texsplat::sg
