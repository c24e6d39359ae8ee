#include "scenegraph/NodeRegistry.h"

#include "FakeValueReader.h"
#include "TestNodes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/Separator.h"
#include "scenegraph/Switch.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

// An application's own node type, unknown to the library.
class Wobble : public Declare<Wobble, Node> {
public:
    static constexpr const char* kTypeName = "Wobble";
    SFFloat amplitude;
    MFVec3f points;

protected:
    Wobble() {
        addField(amplitude, "amplitude", 0.25f, "Height of the wave");
        addField(points, "points", std::vector<glm::vec3>{}, "Sample positions");
    }
};

// Another class claiming the same scene-file name.
class FakeGroup : public Declare<FakeGroup, Node> {
public:
    static constexpr const char* kTypeName = "Group";
};

TEST(NodeRegistry, knowsTheCoreTypes) {
    NodeRegistry& registry = NodeRegistry::instance();
    EXPECT_EQ(registry.find("Group"), &Group::classType());
    EXPECT_EQ(registry.find("Separator"), &Separator::classType());
    EXPECT_EQ(registry.find("Switch"), &Switch::classType());
    EXPECT_EQ(registry.find("Nothing"), nullptr);
    std::shared_ptr<FieldContainer> created = registry.create("Switch");
    ASSERT_NE(created, nullptr);
    EXPECT_EQ(&created->type(), &Switch::classType());
}

TEST(NodeRegistry, userTypesAreCreatedAndFilledGenerically) {
    NodeRegistry& registry = NodeRegistry::instance();
    registry.add<Wobble>();
    registry.add<Wobble>();
    std::shared_ptr<FieldContainer> created = registry.create("Wobble");
    ASSERT_NE(created->asNode(), nullptr);
    // What a reader does: look fields up by name and let them parse their value.
    Field* amplitude = created->findField("amplitude");
    ASSERT_NE(amplitude, nullptr);
    EXPECT_EQ(amplitude->typeName(), "SFFloat");
    EXPECT_TRUE(amplitude->isDefault());
    test::FakeValueReader reader("0.5");
    amplitude->readValue(reader);
    // What a writer does: list the fields that differ from their defaults.
    std::vector<std::string> written;
    for (const Field* field : created->fields()) {
        if (!field->isDefault()) {
            written.push_back(std::string(field->typeName()) + " " + field->name() + " " +
                              field->valueText());
        }
    }
    EXPECT_EQ(written, std::vector<std::string>{"SFFloat amplitude 0.5"});
    EXPECT_EQ(std::static_pointer_cast<Wobble>(created)->amplitude.value(), 0.5f);
    const std::vector<const NodeType*> types = registry.types();
    EXPECT_NE(std::find(types.begin(), types.end(), &Wobble::classType()), types.end());
}

TEST(NodeRegistry, unknownAbstractAndClashingNamesAreErrors) {
    NodeRegistry& registry = NodeRegistry::instance();
    try {
        registry.create("Nothing");
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "unknown node type 'Nothing'");
    }
    try {
        registry.add<FakeGroup>();
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "cannot register node type 'Group': another type is already "
                                   "registered under that name");
    }
    EXPECT_EQ(registry.find("Group"), &Group::classType());
}

} // namespace
} // namespace texsplat::sg
