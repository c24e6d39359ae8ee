#include "scenegraph/fields/SFTrigger.h"

#include "FakeValueReader.h"
#include "TestNodes.h"
#include "scenegraph/fields/Fields.h"

#include <gtest/gtest.h>

#include <string>

namespace texsplat::sg {
namespace {

TEST(SFTrigger, firingNotifiesAndIsNoLongerDefault) {
    SFTrigger trigger;
    trigger.setDefault(true);
    test::RecordingObserver observer;
    trigger.addObserver(observer);
    trigger.setValue();
    EXPECT_EQ(observer.sources.size(), 1u);
    EXPECT_FALSE(trigger.isDefault());
    trigger.removeObserver(observer);
}

TEST(SFTrigger, readsAndWritesNoValue) {
    SFTrigger trigger;
    trigger.setDefault(true);
    test::FakeValueReader reader("TRUE");
    trigger.readValue(reader);
    EXPECT_FALSE(trigger.isDefault()); // reading fires it
    EXPECT_FALSE(reader.isAtEnd());    // and leaves what follows to the next field
    EXPECT_EQ(trigger.typeName(), "SFTrigger");
    EXPECT_EQ(trigger.valueText(), "");
}

TEST(SFTrigger, connectsOnlyToTriggers) {
    SFTrigger source;
    SFTrigger follower;
    follower.connectFrom(source);
    test::RecordingObserver observer;
    follower.addObserver(observer);
    source.setValue();
    EXPECT_EQ(observer.sources.size(), 1u);
    follower.removeObserver(observer);

    SFBool flag;
    EXPECT_EQ(test::connectError(follower, flag),
              "cannot connect SFTrigger <standalone> from SFBool <standalone>: the types differ");
}

} // namespace
} // namespace texsplat::sg
