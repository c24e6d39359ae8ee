#include "scenegraph/fields/SField.h"

#include "FakeValueReader.h"
#include "scenegraph/Error.h"
#include "scenegraph/fields/Fields.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace texsplat::sg {
namespace {

// Reads `text` into `field`, checking that all of it was consumed.
template <class F> void read(F& field, const std::string& text) {
    test::FakeValueReader reader(text);
    field.readValue(reader);
    EXPECT_TRUE(reader.isAtEnd()) << text;
}

// Writing a value and reading the text back gives the same value.
template <class F> void expectRoundTrip(const typename F::Value& value) {
    F written;
    written.setValue(value);
    F readBack;
    read(readBack, written.valueText());
    EXPECT_EQ(readBack.value(), value) << written.valueText();
}

TEST(SField, startsAtZeroValueAndDefault) {
    SFFloat size;
    EXPECT_EQ(size.value(), 0.0f);
    EXPECT_TRUE(size.isDefault());
    size = 1.5f;
    EXPECT_EQ(size.value(), 1.5f);
    EXPECT_FALSE(size.isDefault());
    size.setDefault(true);
    EXPECT_TRUE(size.isDefault());
    EXPECT_EQ(size.value(), 1.5f);
}

TEST(SField, typeNames) {
    EXPECT_EQ(SFBool().typeName(), "SFBool");
    EXPECT_EQ(SFInt32().typeName(), "SFInt32");
    EXPECT_EQ(SFFloat().typeName(), "SFFloat");
    EXPECT_EQ(SFString().typeName(), "SFString");
    EXPECT_EQ(SFVec2f().typeName(), "SFVec2f");
    EXPECT_EQ(SFVec3f().typeName(), "SFVec3f");
    EXPECT_EQ(SFColor().typeName(), "SFColor");
    EXPECT_EQ(SFRotation().typeName(), "SFRotation");
    EXPECT_EQ(SFMatrix().typeName(), "SFMatrix");
}

TEST(SField, boolFormatsAndReadsInventorNames) {
    SFBool flag;
    EXPECT_EQ(flag.valueText(), "FALSE");
    flag = true;
    EXPECT_EQ(flag.valueText(), "TRUE");
    read(flag, "FALSE");
    EXPECT_FALSE(flag.value());
    read(flag, "1");
    EXPECT_TRUE(flag.value());
    read(flag, "0");
    EXPECT_FALSE(flag.value());
}

TEST(SField, boolRejectsOtherWords) {
    SFBool flag;
    test::FakeValueReader reader("YES");
    try {
        flag.readValue(reader);
        FAIL() << "no error";
    } catch (const ParseError& error) {
        EXPECT_STREQ(error.what(), "fake.iv:1:4: expected TRUE or FALSE, got 'YES'");
    }
}

TEST(SField, int32FormatsAndReads) {
    SFInt32 count;
    count = -42;
    EXPECT_EQ(count.valueText(), "-42");
    read(count, "2147483647");
    EXPECT_EQ(count.value(), 2147483647);
    expectRoundTrip<SFInt32>(std::numeric_limits<std::int32_t>::min());
}

TEST(SField, floatUsesShortestRoundTripText) {
    SFFloat value;
    value = 1.6f;
    EXPECT_EQ(value.valueText(), "1.6");
    value = 2.0f;
    EXPECT_EQ(value.valueText(), "2");
    value = 1e20f;
    EXPECT_EQ(value.valueText(), "1e+20");
    for (float f : {0.1f, 1.0f / 3.0f, 1.556228f, 0.889392f, -7.5e-39f, 3.4028235e38f,
                    std::numeric_limits<float>::denorm_min(), std::nextafter(1.0f, 2.0f)}) {
        expectRoundTrip<SFFloat>(f);
    }
}

TEST(SField, stringIsQuotedWithEscapes) {
    SFString text;
    EXPECT_EQ(text.valueText(), "\"\"");
    text = std::string("say \"hi\" \\ bye");
    EXPECT_EQ(text.valueText(), "\"say \\\"hi\\\" \\\\ bye\"");
    expectRoundTrip<SFString>("say \"hi\" \\ bye");
}

TEST(SField, vectorsAndColor) {
    SFVec2f v2;
    v2 = glm::vec2(1.0f, -0.5f);
    EXPECT_EQ(v2.valueText(), "1 -0.5");
    SFVec3f v3;
    read(v3, "0.1 2 3e-5");
    EXPECT_EQ(v3.value(), glm::vec3(0.1f, 2.0f, 3e-5f));
    EXPECT_EQ(v3.valueText(), "0.1 2 3e-05");
    SFColor color;
    EXPECT_EQ(color.value(), glm::vec3(0.0f));
    color = glm::vec3(1.0f, 0.5f, 0.25f);
    EXPECT_EQ(color.valueText(), "1 0.5 0.25");
    expectRoundTrip<SFColor>(glm::vec3(0.3f, 0.6f, 0.9f));
}

TEST(SField, rotationIsAxisAndRadians) {
    SFRotation rotation;
    EXPECT_EQ(rotation.value(), Rotation());
    EXPECT_EQ(rotation.valueText(), "0 0 1 0");
    read(rotation, "0 1 0 1.5707964");
    EXPECT_EQ(rotation.value().axis(), glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(rotation.value().angle(), 1.5707964f);
    const glm::vec3 rotated = glm::vec3(rotation.value().matrix() * glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(rotated.x, 0.0f, 1e-6f);
    EXPECT_NEAR(rotated.z, -1.0f, 1e-6f);
    expectRoundTrip<SFRotation>(Rotation(glm::vec3(1.0f, 2.0f, 3.0f), 0.7f));
}

TEST(SField, matrixUsesInventorRowOrder) {
    SFMatrix matrix;
    EXPECT_EQ(matrix.value(), glm::mat4(1.0f));
    matrix = glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, 6.0f, 7.0f));
    // Inventor's row-vector matrices keep the translation in the last row of the text.
    EXPECT_EQ(matrix.valueText(), "1 0 0 0 0 1 0 0 0 0 1 0 5 6 7 1");
    read(matrix, "2 0 0 0 0 2 0 0 0 0 2 0 1 2 3 1");
    const glm::vec4 moved = matrix.value() * glm::vec4(1.0f, 1.0f, 1.0f, 1.0f);
    EXPECT_EQ(moved, glm::vec4(3.0f, 4.0f, 5.0f, 1.0f));
}

TEST(SField, readErrorsComeFromTheReader) {
    SFVec3f v3;
    test::FakeValueReader reader("1 2");
    try {
        v3.readValue(reader);
        FAIL() << "no error";
    } catch (const ParseError& error) {
        EXPECT_STREQ(error.what(), "fake.iv:1:4: unexpected end of input");
    }
    EXPECT_TRUE(v3.isDefault());
}

TEST(SField, copyValueFromRejectsOtherTypes) {
    SFVec3f vector;
    SFColor color;
    color = glm::vec3(1.0f);
    try {
        vector.copyValueFrom(color);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "cannot copy SFColor <standalone> into SFVec3f <standalone>");
    }
    SFVec3f other;
    other = glm::vec3(4.0f);
    vector.copyValueFrom(other);
    EXPECT_EQ(vector.value(), glm::vec3(4.0f));
}

} // namespace
} // namespace texsplat::sg
