// NodeType::fieldDescription(): the meaning a class declares with addField() and addOutput(),
// kept once per type.
#include "scenegraph/NodeType.h"

#include "TestNodes.h"
#include "scenegraph/Separator.h"
#include "scenegraph/fields/SFNode.h"

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

namespace texsplat::sg {
namespace {

// A type derived from a concrete one: its own field and its base's.
class LabelledCube : public Declare<LabelledCube, test::TestCube> {
public:
    static constexpr const char* kTypeName = "LabelledCube";
    SFString label;

protected:
    LabelledCube() { addField(label, "label", std::string(), "Text shown next to the cube"); }
};

// Its constructor makes another node, whose field of the same name declares another meaning.
class CubeHolder : public Declare<CubeHolder, Node> {
public:
    static constexpr const char* kTypeName = "CubeHolder";
    SFNode cube;
    SFFloat size;

protected:
    CubeHolder() {
        addField(cube, "cube", std::shared_ptr<Node>(test::TestCube::create()), "The held cube");
        addField(size, "size", 1.0f, "Scale of the held cube");
    }
};

TEST(FieldDescription, isWhatTheConstructorDeclared) {
    EXPECT_EQ(test::TestCube::classType().fieldDescription("size"), "Edge length");
    EXPECT_EQ(test::TestDoubler::classType().fieldDescription("output"), "Twice input");
    EXPECT_EQ(Separator::classType().fieldDescription("renderCaching"),
              "Inventor's render-cache hint; read and written back, not used by texsplat");
}

TEST(FieldDescription, ofADerivedTypeCoversItsBaseClassFields) {
    EXPECT_EQ(LabelledCube::classType().fieldDescription("label"), "Text shown next to the cube");
    EXPECT_EQ(LabelledCube::classType().fieldDescription("size"), "Edge length");
}

TEST(FieldDescription, comesFromTheTypesOwnInstanceNotFromNodesItsConstructorMakes) {
    EXPECT_EQ(CubeHolder::classType().fieldDescription("size"), "Scale of the held cube");
    EXPECT_EQ(CubeHolder::classType().fieldDescription("cube"), "The held cube");
}

TEST(FieldDescription, isEmptyForUnknownNamesAndAbstractTypes) {
    EXPECT_EQ(test::TestCube::classType().fieldDescription("colour"), "");
    EXPECT_EQ(Node::classType().fieldDescription("size"), "");
}

TEST(FieldDescription, isCollectedOnceWhenThreadsAskTogether) {
    std::vector<std::thread> threads;
    std::vector<std::string> seen(4);
    for (std::size_t i = 0; i < seen.size(); ++i) {
        threads.emplace_back(
            [&seen, i] { seen[i] = LabelledCube::classType().fieldDescription("label"); });
    }
    for (std::thread& thread : threads) {
        thread.join();
    }
    for (const std::string& text : seen) {
        EXPECT_EQ(text, "Text shown next to the cube");
    }
}

} // namespace
} // namespace texsplat::sg
