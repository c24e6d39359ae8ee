#include "scenegraph/fields/Field.h"

#include "SceneTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace texsplat::sg;
using namespace texsplat::sg::test;
using texsplat::DataError;
using texsplat::ParseError;

namespace {

constexpr std::size_t kLimit = Field::kMaxConnectionChain;

// `count` named cubes, each connected from the one before: count - 1 links.
std::vector<TestCube::Ptr> cubeChain(std::size_t count, const std::string& prefix = "c") {
    std::vector<TestCube::Ptr> cubes;
    for (std::size_t i = 0; i < count; ++i) {
        cubes.push_back(TestCube::create());
        cubes.back()->setName(prefix + std::to_string(i));
        if (i > 0) {
            cubes[i]->size.connectFrom(cubes[i - 1]->size);
        }
    }
    return cubes;
}

// A file of `count` cubes, each but the first connected from the one before, one per line
// after the header.
std::string chainFile(std::size_t count) {
    std::string text = "#Inventor V2.1 ascii\nDEF c0 TestCube { size 1 }\n";
    for (std::size_t i = 1; i < count; ++i) {
        text += "DEF c" + std::to_string(i) + " TestCube { size = USE c" + std::to_string(i - 1) +
                " . size }\n";
    }
    return text;
}

class ConnectionChainTest : public ::testing::Test {
protected:
    void SetUp() override { registerSceneTestTypes(); }
};

TEST_F(ConnectionChainTest, aChainAtTheLimitPropagates) {
    const std::vector<TestCube::Ptr> cubes = cubeChain(kLimit + 1);
    cubes.front()->size.setValue(5.0f);
    EXPECT_EQ(cubes.back()->size.value(), 5.0f);
}

TEST_F(ConnectionChainTest, aLinkPastTheLimitIsRejected) {
    const std::vector<TestCube::Ptr> cubes = cubeChain(kLimit + 1);
    const TestCube::Ptr next = TestCube::create();
    EXPECT_EQ(connectError(next->size, cubes.back()->size),
              "cannot connect SFFloat TestCube.size from SFFloat TestCube(c1000).size: "
              "connection chain longer than the limit of 1000 links");
    EXPECT_FALSE(next->size.isConnected());
}

TEST_F(ConnectionChainTest, linksBelowTheNewConnectionCountToo) {
    // Two chains of 500 links; joining them makes 1001.
    const std::vector<TestCube::Ptr> upper = cubeChain(kLimit / 2 + 1, "u");
    const std::vector<TestCube::Ptr> lower = cubeChain(kLimit / 2 + 1, "l");
    EXPECT_EQ(connectError(lower.front()->size, upper.back()->size),
              "cannot connect SFFloat TestCube(l0).size from SFFloat TestCube(u500).size: "
              "connection chain longer than the limit of 1000 links");
    // Without the last link of the lower chain they fit exactly.
    lower.back()->size.disconnect();
    lower.front()->size.connectFrom(upper.back()->size);
    upper.front()->size.setValue(3.0f);
    EXPECT_EQ(lower[kLimit / 2 - 1]->size.value(), 3.0f);
}

TEST_F(ConnectionChainTest, anEngineIsALinkFromItsInputsToItsOutputs) {
    // c0 -> doubler.input -> doubler.output -> c1 ... : three links per engine.
    std::vector<TestCube::Ptr> cubes{TestCube::create()};
    for (std::size_t i = 0; i < kLimit / 3; ++i) {
        const TestDoubler::Ptr doubler = TestDoubler::create();
        doubler->input.connectFrom(cubes.back()->size);
        cubes.push_back(TestCube::create());
        cubes.back()->size.connectFrom(doubler->output);
    }
    const TestCube::Ptr last = TestCube::create();
    last->size.connectFrom(cubes.back()->size); // link 1000
    const TestCube::Ptr past = TestCube::create();
    EXPECT_EQ(connectError(past->size, last->size),
              "cannot connect SFFloat TestCube.size from SFFloat TestCube.size: connection chain "
              "longer than the limit of 1000 links");
    cubes.front()->size.setValue(0.0f);
    EXPECT_EQ(last->size.value(), 0.0f);
}

TEST_F(ConnectionChainTest, aFileWithAChainAtTheLimitReadsAndPropagates) {
    const auto root = std::dynamic_pointer_cast<Separator>(
        SceneReader::readString(chainFile(kLimit + 1), "chain.iv"));
    ASSERT_NE(root, nullptr);
    ASSERT_EQ(root->childCount(), kLimit + 1);
    static_cast<TestCube&>(*root->child(0)).size.setValue(7.0f);
    EXPECT_EQ(static_cast<TestCube&>(*root->child(kLimit)).size.value(), 7.0f);
}

TEST_F(ConnectionChainTest, aFileWithALongerChainFailsAtTheFirstLinkPastTheLimit) {
    const std::string message =
        "chain.iv:1003:41: cannot connect SFFloat TestCube(c1001).size from SFFloat "
        "TestCube(c1000).size: connection chain longer than the limit of 1000 links";
    EXPECT_EQ(readError(chainFile(kLimit + 2), "chain.iv"), message);
    // A chain sixteen times longer stops at the same place: the reader never walks a chain of
    // more than 1000 links, so the work is bounded by 1000 per connection read.
    EXPECT_EQ(readError(chainFile(16 * kLimit), "chain.iv"), message);
}

} // namespace
