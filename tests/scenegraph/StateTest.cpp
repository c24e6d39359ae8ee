#include "scenegraph/actions/State.h"

#include "scenegraph/actions/ModelMatrixElement.h"

#include <gtest/gtest.h>

#include <string>

namespace texsplat::sg {
namespace {

// An element a later action might add.
struct LabelElement {
    std::string label = "none";
};

TEST(State, elementsStartDefault) {
    State state;
    EXPECT_EQ(state.get<ModelMatrixElement>().matrix, glm::mat4(1.0f));
    EXPECT_EQ(state.get<LabelElement>().label, "none");
    EXPECT_EQ(state.depth(), 0u);
}

TEST(State, popRestoresWhatWasModifiedSinceThePush) {
    State state;
    state.modify<LabelElement>().label = "outer";
    state.push();
    state.modify<LabelElement>().label = "inner";
    state.modify<LabelElement>().label = "inner2";
    state.modify<ModelMatrixElement>().matrix[3][0] = 5.0f;
    state.push();
    state.modify<LabelElement>().label = "deepest";
    EXPECT_EQ(state.depth(), 2u);
    state.pop();
    EXPECT_EQ(state.get<LabelElement>().label, "inner2");
    EXPECT_EQ(state.get<ModelMatrixElement>().matrix[3][0], 5.0f);
    state.pop();
    EXPECT_EQ(state.get<LabelElement>().label, "outer");
    EXPECT_EQ(state.get<ModelMatrixElement>().matrix, glm::mat4(1.0f));
}

TEST(State, resetForgetsEverything) {
    State state;
    state.push();
    state.modify<LabelElement>().label = "x";
    state.reset();
    EXPECT_EQ(state.depth(), 0u);
    EXPECT_EQ(state.get<LabelElement>().label, "none");
}

} // namespace
} // namespace texsplat::sg
