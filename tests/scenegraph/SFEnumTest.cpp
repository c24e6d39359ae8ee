#include "scenegraph/fields/SFEnum.h"

#include "FakeValueReader.h"
#include "scenegraph/Declare.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

enum class Operator { Modulate, Blend };
const EnumNames kOperatorNames{{"MODULATE", Operator::Modulate}, {"BLEND", Operator::Blend}};

class Splat : public Declare<Splat, Node> {
public:
    static constexpr const char* kTypeName = "Splat";
    SFEnum textureOperator;

protected:
    Splat() {
        addField(textureOperator, "operator", Operator::Blend, kOperatorNames, "Texture operator");
    }
};

TEST(SFEnum, defaultNamesAndTypedAccess) {
    Splat::Ptr splat = Splat::create();
    EXPECT_EQ(splat->textureOperator.typeName(), "SFEnum");
    EXPECT_TRUE(splat->textureOperator.isDefault());
    EXPECT_EQ(splat->textureOperator.as<Operator>(), Operator::Blend);
    EXPECT_EQ(splat->textureOperator.valueText(), "BLEND");
    splat->textureOperator.setValue(Operator::Modulate);
    EXPECT_EQ(splat->textureOperator.value(), 0);
    EXPECT_EQ(splat->textureOperator.valueText(), "MODULATE");
    EXPECT_FALSE(splat->textureOperator.isDefault());
}

TEST(SFEnum, setsAndAnswersValueNamesAsTheReaderDoes) {
    Splat::Ptr splat = Splat::create();
    splat->textureOperator.setValueName("MODULATE");
    EXPECT_EQ(splat->textureOperator.as<Operator>(), Operator::Modulate);
    EXPECT_EQ(splat->textureOperator.valueName(), "MODULATE");
    EXPECT_FALSE(splat->textureOperator.isDefault());
    try {
        splat->textureOperator.setValueName("ADD");
        FAIL() << "no error for an unknown name";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "unknown value 'ADD' for SFEnum Splat.operator (expected one "
                                   "of MODULATE, BLEND)");
    }
    EXPECT_EQ(splat->textureOperator.valueName(), "MODULATE");
}

TEST(SFEnum, readsNames) {
    Splat::Ptr splat = Splat::create();
    test::FakeValueReader reader("MODULATE");
    splat->textureOperator.readValue(reader);
    EXPECT_EQ(splat->textureOperator.as<Operator>(), Operator::Modulate);
}

TEST(SFEnum, unknownNameIsAParseErrorListingTheNames) {
    Splat::Ptr splat = Splat::create();
    splat->setName("s1");
    test::FakeValueReader reader("ADD");
    try {
        splat->textureOperator.readValue(reader);
        FAIL() << "no error";
    } catch (const ParseError& error) {
        EXPECT_STREQ(error.what(), "fake.iv:1:4: unknown value 'ADD' for SFEnum "
                                   "Splat(s1).operator (expected one of MODULATE, BLEND)");
    }
}

TEST(SFEnum, valueOutsideTheNamesIsADataError) {
    Splat::Ptr splat = Splat::create();
    try {
        splat->textureOperator.setValue(7);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "SFEnum Splat.operator: 7 is not a value of this enum "
                                   "(expected one of MODULATE, BLEND)");
    }
    EXPECT_EQ(splat->textureOperator.as<Operator>(), Operator::Blend);
}

TEST(SFEnum, withoutNamesWritesNumbersAndCannotRead) {
    SFEnum plain;
    plain.setValue(3);
    EXPECT_EQ(plain.valueText(), "3");
    test::FakeValueReader reader("BLEND");
    EXPECT_THROW(plain.readValue(reader), ParseError);
}

} // namespace
} // namespace texsplat::sg
