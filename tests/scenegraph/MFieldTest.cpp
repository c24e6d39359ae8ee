#include "scenegraph/fields/MField.h"

#include "FakeValueReader.h"
#include "scenegraph/fields/Fields.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace texsplat::sg {
namespace {

// Records the writer calls a field makes.
class RecordingWriter final : public FieldValueWriter {
public:
    void writeToken(std::string_view text) override { calls.push_back(std::string(text)); }
    void writeNode(const Node::Ptr& node) override {
        calls.push_back(node ? node->typeName() : "NULL");
    }
    void beginList() override { calls.push_back("begin"); }
    void endList() override { calls.push_back("end"); }
    std::vector<std::string> calls;
};

TEST(MField, typeNamesAndEmptyDefault) {
    EXPECT_EQ(MFInt32().typeName(), "MFInt32");
    EXPECT_EQ(MFFloat().typeName(), "MFFloat");
    EXPECT_EQ(MFVec3f().typeName(), "MFVec3f");
    EXPECT_EQ(MFColor().typeName(), "MFColor");
    EXPECT_EQ(MFString().typeName(), "MFString");
    EXPECT_EQ(MFBool().typeName(), "MFBool");
    EXPECT_EQ(MFVec2f().typeName(), "MFVec2f");
    EXPECT_EQ(MFRotation().typeName(), "MFRotation");
    EXPECT_EQ(MFMatrix().typeName(), "MFMatrix");
    MFFloat values;
    EXPECT_TRUE(values.isEmpty());
    EXPECT_TRUE(values.isDefault());
    EXPECT_EQ(values.valueText(), "[]");
}

TEST(MField, setAndSet1ValueGrowWithZeros) {
    MFInt32 values;
    values.setValue({1, 2, 3});
    EXPECT_EQ(values.size(), 3u);
    EXPECT_EQ(values[1], 2);
    values.set1Value(5, 9);
    EXPECT_EQ(values.values(), (std::vector<std::int32_t>{1, 2, 3, 0, 0, 9}));
    EXPECT_FALSE(values.isDefault());
}

TEST(MField, oneValueIsWrittenWithoutBrackets) {
    MFFloat values;
    values.setValue({0.5f});
    EXPECT_EQ(values.valueText(), "0.5");
    values.setValue({0.5f, 1.6f});
    EXPECT_EQ(values.valueText(), "[ 0.5, 1.6 ]");
    RecordingWriter writer;
    values.writeValue(writer);
    EXPECT_EQ(writer.calls, (std::vector<std::string>{"begin", "0.5", "1.6", "end"}));
}

TEST(MField, readsBracketsCommasOptionalAndSingleValue) {
    MFVec3f points;
    test::FakeValueReader list("[ 1 2 3, 4 5 6 7 8 9, ]");
    points.readValue(list);
    EXPECT_TRUE(list.isAtEnd());
    ASSERT_EQ(points.size(), 3u);
    EXPECT_EQ(points[2], glm::vec3(7.0f, 8.0f, 9.0f));
    test::FakeValueReader single("1 0 0");
    points.readValue(single);
    EXPECT_EQ(points.values(), std::vector<glm::vec3>{glm::vec3(1.0f, 0.0f, 0.0f)});
    test::FakeValueReader empty("[]");
    points.readValue(empty);
    EXPECT_TRUE(points.isEmpty());
    EXPECT_FALSE(points.isDefault());
}

TEST(MField, boolsIndexLikeOtherTypes) {
    MFBool flags;
    flags.setValue({true, false});
    EXPECT_TRUE(flags[0]);
    EXPECT_FALSE(flags[1]);
    EXPECT_EQ(flags.valueText(), "[ TRUE, FALSE ]");
}

TEST(MField, stringsAndColorsRoundTrip) {
    MFString names;
    names.setValue({"a b", "c\"d"});
    EXPECT_EQ(names.valueText(), "[ \"a b\", \"c\\\"d\" ]");
    test::FakeValueReader reader(names.valueText());
    MFString readBack;
    readBack.readValue(reader);
    EXPECT_EQ(readBack.values(), names.values());

    MFColor colors;
    colors.setValue({glm::vec3(0.1f, 0.2f, 0.3f), glm::vec3(1.0f)});
    test::FakeValueReader colorReader(colors.valueText());
    MFColor colorsBack;
    colorsBack.readValue(colorReader);
    EXPECT_EQ(colorsBack.values(), colors.values());
}

TEST(MField, readingAnUnterminatedListFails) {
    MFFloat values;
    test::FakeValueReader reader("[ 1, 2");
    EXPECT_THROW(values.readValue(reader), ParseError);
}

} // namespace
} // namespace texsplat::sg
