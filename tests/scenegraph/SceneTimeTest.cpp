#include "scenegraph/engines/SceneTime.h"

#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/engines/ElapsedTime.h"

#include "TestNodes.h"

#include <gtest/gtest.h>

#include <string>

using namespace texsplat;
using namespace texsplat::sg;

namespace {

// A group holding a cube whose size follows an ElapsedTime at `speed`.
struct AnimatedScene {
    explicit AnimatedScene(float speed) {
        elapsed->speed.setValue(speed);
        cube->size.connectFrom(elapsed->timeOut);
        root->addChild(cube);
    }
    Group::Ptr root = Group::create();
    test::TestCube::Ptr cube = test::TestCube::create();
    ElapsedTime::Ptr elapsed = ElapsedTime::create();
};

} // namespace

TEST(SceneTime, startsAtZeroAndMovesTheEnginesToTheTimeAsked) {
    AnimatedScene scene(2.0f);
    SceneTime time(*scene.root);
    EXPECT_EQ(time.time(), 0.0);
    EXPECT_FLOAT_EQ(scene.cube->size.value(), 0.0f);
    time.setTime(1.5);
    EXPECT_EQ(time.time(), 1.5);
    EXPECT_FLOAT_EQ(scene.cube->size.value(), 3.0f);
}

TEST(SceneTime, anEarlierTimeShowsWhatThatTimeShowsFirst) {
    AnimatedScene scene(2.0f);
    SceneTime time(*scene.root);
    time.setTime(0.25);
    const float quarter = scene.cube->size.value();
    time.setTime(4.0);
    time.setTime(0.25);
    EXPECT_EQ(time.time(), 0.25);
    EXPECT_EQ(scene.cube->size.value(), quarter);
    EXPECT_FLOAT_EQ(quarter, 0.5f);
}

TEST(SceneTime, refusesTimesTheSceneCannotShow) {
    AnimatedScene scene(1.0f);
    SceneTime time(*scene.root);
    for (const double bad : {-1.0, 1e300}) {
        try {
            time.setTime(bad);
            FAIL() << "no error for " << bad;
        } catch (const DataError& error) {
            EXPECT_EQ(std::string(error.what()).rfind(
                          "time: expected a finite number of seconds >= 0, got ", 0),
                      0u)
                << error.what();
        }
    }
    EXPECT_EQ(time.time(), 0.0);
}
