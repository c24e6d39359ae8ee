#include "scenegraph/engines/ElapsedTime.h"

#include "scenegraph/Error.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"

#include "SceneTestSupport.h"

#include <gtest/gtest.h>

#include <memory>

using namespace texsplat::sg;

namespace {

/// Feeds `time` to the engine as the queue's time field would.
float at(ElapsedTime& engine, float time) {
    engine.timeIn = time;
    return engine.timeOut.value();
}

} // namespace

TEST(ElapsedTime, countsFromTheFirstInputTime) {
    auto elapsed = ElapsedTime::create();
    EXPECT_EQ(elapsed->speed.value(), 1.0f);
    EXPECT_TRUE(elapsed->on.value());
    EXPECT_FALSE(elapsed->pause.value());
    elapsed->speed = 1.0f; // inputs set before the first time do not start the count
    EXPECT_EQ(at(*elapsed, 10.0f), 0.0f);
    EXPECT_EQ(at(*elapsed, 10.5f), 0.5f);
    EXPECT_EQ(at(*elapsed, 13.0f), 3.0f);
}

TEST(ElapsedTime, speedTwoRunsTwiceAsFast) {
    auto elapsed = ElapsedTime::create();
    elapsed->speed = 2.0f;
    at(*elapsed, 1.0f);
    EXPECT_EQ(at(*elapsed, 2.0f), 2.0f);
    EXPECT_EQ(at(*elapsed, 3.5f), 5.0f);
}

TEST(ElapsedTime, negativeSpeedRunsBackwards) {
    auto elapsed = ElapsedTime::create();
    elapsed->speed = -1.0f;
    at(*elapsed, 1.0f);
    EXPECT_EQ(at(*elapsed, 2.0f), -1.0f);
    EXPECT_EQ(at(*elapsed, 4.0f), -3.0f);
}

TEST(ElapsedTime, speedChangeAppliesFromWhenItIsMade) {
    auto elapsed = ElapsedTime::create();
    at(*elapsed, 0.0f);
    EXPECT_EQ(at(*elapsed, 2.0f), 2.0f);
    elapsed->speed = 3.0f;
    EXPECT_EQ(at(*elapsed, 3.0f), 5.0f);
    elapsed->speed = -1.0f;
    EXPECT_EQ(at(*elapsed, 4.0f), 4.0f);
}

TEST(ElapsedTime, pauseFreezesTheOutputWhileTimeKeepsCounting) {
    auto elapsed = ElapsedTime::create();
    at(*elapsed, 0.0f);
    EXPECT_EQ(at(*elapsed, 1.0f), 1.0f);
    elapsed->pause = true;
    EXPECT_EQ(at(*elapsed, 2.0f), 1.0f);
    EXPECT_EQ(at(*elapsed, 3.0f), 1.0f);
    elapsed->pause = false;
    EXPECT_EQ(elapsed->timeOut.value(), 3.0f);
    EXPECT_EQ(at(*elapsed, 4.0f), 4.0f);
}

TEST(ElapsedTime, offStopsTheClockAndOnResumesWhereItStopped) {
    auto elapsed = ElapsedTime::create();
    at(*elapsed, 0.0f);
    EXPECT_EQ(at(*elapsed, 1.0f), 1.0f);
    elapsed->on = false;
    EXPECT_EQ(at(*elapsed, 3.0f), 1.0f);
    elapsed->on = true;
    EXPECT_EQ(at(*elapsed, 4.0f), 2.0f);
}

TEST(ElapsedTime, resetRestartsAtZero) {
    auto elapsed = ElapsedTime::create();
    elapsed->speed = 2.0f;
    at(*elapsed, 0.0f);
    EXPECT_EQ(at(*elapsed, 5.0f), 10.0f);
    elapsed->reset.touch();
    EXPECT_EQ(elapsed->timeOut.value(), 0.0f);
    EXPECT_EQ(at(*elapsed, 6.0f), 2.0f);
    elapsed->reset.setValue();
    EXPECT_EQ(at(*elapsed, 6.5f), 1.0f);
}

// Inventor's reset is an SFTrigger: its name alone, no value (Coin rejects `reset TRUE`).
TEST(ElapsedTime, resetIsWrittenAndReadAsItsNameAlone) {
    test::registerSceneTestTypes();
    const auto cube = test::TestCube::create();
    const auto elapsed = ElapsedTime::create();
    cube->size.connectFrom(elapsed->timeOut);
    elapsed->reset.setValue();
    const std::string text = WriteAction::writeString(*cube);
    EXPECT_NE(text.find("    size = ElapsedTime {\n        reset\n    } . timeOut\n"),
              std::string::npos)
        << text;
    const Node::Ptr copy = SceneReader::readString(text, "reset.iv");
    EXPECT_EQ(test::graphDifference(*cube, *copy), "");
    EXPECT_EQ(test::readError("#Inventor V2.1 ascii\n"
                              "TestCube { size = ElapsedTime { reset TRUE } . timeOut }\n",
                              "value.iv"),
              "value.iv:2:39: unknown field 'TRUE' of ElapsedTime (fields: timeIn, speed, on, "
              "pause, reset)");
}

TEST(ElapsedTime, pausedEngineDoesNotNotifyConnectedFields) {
    auto elapsed = ElapsedTime::create();
    auto cube = test::TestCube::create();
    cube->size.connectFrom(elapsed->timeOut);
    at(*elapsed, 0.0f);
    at(*elapsed, 1.0f);
    EXPECT_EQ(cube->size.value(), 1.0f);
    elapsed->pause = true;
    test::RecordingObserver observer;
    cube->size.addObserver(observer);
    at(*elapsed, 2.0f);
    at(*elapsed, 3.0f);
    EXPECT_TRUE(observer.subjects.empty());
    elapsed->pause = false;
    EXPECT_EQ(cube->size.value(), 3.0f);
    EXPECT_EQ(observer.subjects.size(), 1u);
    cube->size.removeObserver(observer);
}

TEST(ElapsedTime, queueTimeDrivesTheScene) {
    SimulatedClock clock(100.0);
    SensorQueue queue(clock);
    auto elapsed = ElapsedTime::create();
    elapsed->speed = 2.0f;
    elapsed->timeIn.connectFrom(queue.timeField());
    auto cube = test::TestCube::create();
    cube->size.connectFrom(elapsed->timeOut);
    EXPECT_EQ(cube->size.value(), 0.0f);
    for (int frame = 1; frame <= 30; ++frame) {
        clock.setTime(100.0 + frame / 30.0);
        queue.process();
    }
    EXPECT_FLOAT_EQ(cube->size.value(), 2.0f);
}

TEST(ElapsedTime, isRegisteredForSceneFiles) {
    NodeRegistry& registry = NodeRegistry::instance();
    registerEngineTypes(registry);
    registerEngineTypes(registry);
    ASSERT_EQ(registry.find("ElapsedTime"), &ElapsedTime::classType());
    auto object = registry.create("ElapsedTime");
    EXPECT_EQ(object->asNode(), nullptr);
    ASSERT_NE(object->findField("speed"), nullptr);
    EXPECT_EQ(object->findField("speed")->typeName(), "SFFloat");
    EXPECT_EQ(object->findField("reset")->typeName(), "SFTrigger");
    auto* engine = dynamic_cast<Engine*>(object.get());
    ASSERT_NE(engine, nullptr);
    ASSERT_NE(engine->findOutput("timeOut"), nullptr);
    EXPECT_EQ(engine->findOutput("timeOut")->typeName(), "SFFloat");
}
