#include "scenegraph/fields/Field.h"

#include "TestNodes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"

#include <gtest/gtest.h>

#include <memory>

namespace texsplat::sg {
namespace {

using test::RecordingObserver;
using test::TestCube;
using test::connectError;

TEST(Field, knowsItsContainerNameAndFullName) {
    TestCube::Ptr cube = TestCube::create();
    EXPECT_EQ(cube->size.name(), "size");
    EXPECT_EQ(cube->size.container(), cube.get());
    EXPECT_EQ(cube->size.fullName(), "TestCube.size");
    cube->setName("box");
    EXPECT_EQ(cube->size.fullName(), "TestCube(box).size");
    EXPECT_EQ(cube->findField("size"), &cube->size);
    EXPECT_EQ(cube->findField("nothing"), nullptr);
}

TEST(Field, settingNotifiesFieldThenContainerObservers) {
    TestCube::Ptr cube = TestCube::create();
    RecordingObserver fieldObserver;
    RecordingObserver nodeObserver;
    cube->size.addObserver(fieldObserver);
    cube->addObserver(nodeObserver);
    cube->size = 4.0f;
    ASSERT_EQ(fieldObserver.subjects.size(), 1u);
    EXPECT_EQ(fieldObserver.subjects[0], &cube->size);
    EXPECT_EQ(fieldObserver.sources[0], &cube->size);
    ASSERT_EQ(nodeObserver.subjects.size(), 1u);
    EXPECT_EQ(nodeObserver.subjects[0], cube.get());
    cube->size.touch();
    EXPECT_EQ(nodeObserver.subjects.size(), 2u);
    EXPECT_FALSE(cube->size.isDefault());
    cube->size.removeObserver(fieldObserver);
    cube->removeObserver(nodeObserver);
}

TEST(Field, touchKeepsTheDefaultFlag) {
    TestCube::Ptr cube = TestCube::create();
    RecordingObserver observer;
    cube->size.addObserver(observer);
    cube->size.touch();
    EXPECT_EQ(observer.subjects.size(), 1u);
    EXPECT_TRUE(cube->size.isDefault());
    cube->size.removeObserver(observer);
}

TEST(Field, aFieldWithNotificationOffTellsNobodyOfAChange) {
    TestCube::Ptr cube = TestCube::create();
    TestCube::Ptr follower = TestCube::create();
    follower->size.connectFrom(cube->size);
    RecordingObserver fieldObserver;
    RecordingObserver nodeObserver;
    cube->size.addObserver(fieldObserver);
    cube->addObserver(nodeObserver);
    EXPECT_TRUE(cube->size.isNotifyEnabled());
    EXPECT_TRUE(cube->size.enableNotify(false));
    EXPECT_FALSE(cube->size.isNotifyEnabled());
    cube->size = 4.0f;
    cube->size.touch();
    EXPECT_EQ(cube->size.value(), 4.0f);
    EXPECT_FALSE(cube->size.isDefault()) << "the value is set all the same";
    EXPECT_TRUE(fieldObserver.subjects.empty());
    EXPECT_TRUE(nodeObserver.subjects.empty());
    EXPECT_NE(follower->size.value(), 4.0f) << "a connected field does not follow";

    EXPECT_FALSE(cube->size.enableNotify(true));
    cube->size = 5.0f;
    EXPECT_EQ(fieldObserver.subjects.size(), 1u);
    EXPECT_EQ(nodeObserver.subjects.size(), 1u);
    EXPECT_EQ(follower->size.value(), 5.0f);
    cube->size.removeObserver(fieldObserver);
    cube->removeObserver(nodeObserver);
}

TEST(Field, observersHearWhenTheFieldDies) {
    RecordingObserver observer;
    Field* address = nullptr;
    {
        TestCube::Ptr cube = TestCube::create();
        cube->size.addObserver(observer);
        address = &cube->size;
    }
    ASSERT_EQ(observer.destroyed.size(), 1u);
    EXPECT_EQ(observer.destroyed[0], address);
}

TEST(Field, fieldToFieldConnectionFollowsTheSource) {
    TestCube::Ptr a = TestCube::create();
    TestCube::Ptr b = TestCube::create();
    a->size = 5.0f;
    b->size.connectFrom(a->size);
    EXPECT_TRUE(b->size.isConnected());
    EXPECT_TRUE(b->size.isDefault());
    EXPECT_EQ(b->size.connectedField(), &a->size);
    EXPECT_EQ(b->size.value(), 5.0f);
    RecordingObserver observer;
    b->addObserver(observer);
    a->size = 6.0f;
    EXPECT_EQ(b->size.value(), 6.0f);
    EXPECT_EQ(observer.subjects.size(), 1u);
    b->size.disconnect();
    a->size = 7.0f;
    EXPECT_EQ(b->size.value(), 6.0f);
    EXPECT_FALSE(b->size.isConnected());
    b->removeObserver(observer);
}

TEST(Field, connectionIsDroppedWhenTheSourceDies) {
    TestCube::Ptr b = TestCube::create();
    {
        TestCube::Ptr a = TestCube::create();
        a->size = 3.0f;
        b->size.connectFrom(a->size);
    }
    EXPECT_FALSE(b->size.isConnected());
    EXPECT_EQ(b->size.value(), 3.0f);
}

TEST(Field, aConnectionCanKeepItsSourceAlive) {
    TestCube::Ptr b = TestCube::create();
    std::weak_ptr<TestCube> source;
    {
        TestCube::Ptr a = TestCube::create();
        source = a;
        b->size.connectFrom(a->size);
        b->size.keepSourceAlive();
    }
    ASSERT_FALSE(source.expired());
    source.lock()->size = 4.0f;
    EXPECT_EQ(b->size.value(), 4.0f);
    b->size.disconnect();
    EXPECT_TRUE(source.expired());
}

TEST(Field, connectingDifferentTypesIsRejected) {
    TestCube::Ptr cube = TestCube::create();
    test::TestTranslation::Ptr move = test::TestTranslation::create();
    EXPECT_EQ(connectError(cube->size, move->translation),
              "cannot connect SFFloat TestCube.size from SFVec3f "
              "TestTranslation.translation: the types differ");
}

TEST(Field, connectionCyclesAreRejectedNamingTheFields) {
    TestCube::Ptr a = TestCube::create();
    TestCube::Ptr b = TestCube::create();
    TestCube::Ptr c = TestCube::create();
    a->setName("a");
    b->setName("b");
    c->setName("c");
    b->size.connectFrom(a->size);
    c->size.connectFrom(b->size);
    EXPECT_EQ(connectError(a->size, c->size),
              "cannot connect SFFloat TestCube(a).size from SFFloat TestCube(c).size: "
              "connection cycle TestCube(a).size <- TestCube(c).size <- TestCube(b).size <- "
              "TestCube(a).size");
    EXPECT_EQ(connectError(a->size, a->size),
              "cannot connect SFFloat TestCube(a).size from SFFloat TestCube(a).size: "
              "connection cycle TestCube(a).size <- TestCube(a).size");
    EXPECT_FALSE(a->size.isConnected());
}

TEST(Field, cyclesThroughEnginesAreRejected) {
    test::TestDoubler::Ptr doubler = test::TestDoubler::create();
    TestCube::Ptr cube = TestCube::create();
    cube->size.connectFrom(doubler->output);
    try {
        doubler->input.connectFrom(cube->size);
        FAIL() << "no error";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(),
                     "cannot connect SFFloat TestDoubler.input from SFFloat TestCube.size: "
                     "connection cycle TestDoubler.input <- TestCube.size <- "
                     "TestDoubler.output <- TestDoubler.input");
    }
}

} // namespace
} // namespace texsplat::sg
