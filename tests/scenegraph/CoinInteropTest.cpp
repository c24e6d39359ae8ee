// Coin3D, a real Open Inventor implementation, reads what WriteAction writes (standard and
// extension nodes), and SceneReader reads what Coin writes. coin_interop_tool is the Coin side.

#include "CoinInteropSupport.h"
#include "SceneTestSupport.h"
#include "scenegraph/Separator.h"
#include "scenegraph/Switch.h"
#include "scenegraph/engines/ElapsedTime.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/UnknownNode.h"
#include "scenegraph/io/WriteAction.h"

#include <gtest/gtest.h>

#include <string>

using namespace texsplat::sg;
using namespace texsplat::sg::test;

namespace {

class CoinInteropTest : public CoinInteropFixture {
protected:
    void SetUp() override {
        CoinInteropFixture::SetUp();
        registerSceneTestTypes();
    }

    // Standard nodes, sharing, names, every field type of an extension node and a pass-through
    // node, both with children. Two limits of Coin 4 shape it: it cannot read NULL in SFNode or
    // MFNode fields of unknown nodes, and it does not count the children of unknown nodes when
    // it decides which nodes are shared (it warns "writeref < 0"), so those are not shared.
    static Node::Ptr makeScene() {
        const auto root = Separator::create();
        root->renderCulling.setValue(CacheEnabled::On);
        const auto shared = Group::create();
        const auto chooser = Switch::create();
        chooser->setName("chooser");
        chooser->whichChild.setValue(0);
        chooser->addChild(shared);
        const auto cube = TestCube::create();
        cube->setName("cube");
        cube->size.setValue(0.1f);
        const auto fields = AllFields::create();
        fields->flag.setValue(false);
        fields->count.setValue(-2147483647 - 1);
        fields->label.setValue("quote \" backslash \\ end");
        fields->offset.setValue({1e-45f, -0.0f});
        fields->position.setValue({3.4028235e38f, -1.0f, 1.0f / 3.0f});
        fields->color.setValue({0.2f, 0.4f, 0.6f});
        fields->orientation.setValue(Rotation({0.0f, 1.0f, 0.0f}, 3.14159274f));
        fields->matrix.setValue(glm::mat4(2.0f));
        fields->quality.setValue(Quality::Final);
        fields->node.setValue(cube);
        fields->indices.setValue({1, -2, 2147483647});
        fields->weights.setValue({0.123456789f, 1e10f});
        fields->points.setValue({{1.0f, 2.0f, 3.0f}, {4.0f, 5.0f, 6.0f}});
        fields->colors.setValue({{1.0f, 0.0f, 0.0f}});
        fields->names.setValue({"two words", "#not a comment"});
        fields->nodes.setValue({cube, Separator::create()});
        fields->addChild(Group::create());
        const UnknownNode::Ptr foreign = UnknownNode::create("ForeignNode");
        foreign->setEnumValue(static_cast<SFEnum&>(foreign->addDescribedField("SFEnum", "mode")),
                              "WEIRD");
        foreign->addDescribedField("MFVec2f", "points").setDefault(false);
        foreign->addChild(Separator::create());
        for (const Node::Ptr& child : {Node::Ptr(chooser), Node::Ptr(shared), Node::Ptr(fields),
                                       Node::Ptr(foreign), Node::Ptr(cube)}) {
            root->addChild(child);
        }
        return root;
    }
};

TEST_F(CoinInteropTest, coinReadsOurStandardAndExtensionNodes) {
    const Node::Ptr scene = makeScene();
    WriteAction::writeFile(*scene, path("ours.iv"));
    const std::string description = runCoin("describe " + path("ours.iv"));
    EXPECT_EQ(description.rfind("Separator\n  renderCulling ON\n", 0), 0u) << description;
    EXPECT_NE(description.find("  Switch \"chooser\"\n    whichChild 0\n    Group\n"),
              std::string::npos)
        << description;
    EXPECT_NE(description.find("  AllFields\n    flag FALSE\n    count -2147483648\n"),
              std::string::npos)
        << description;
    EXPECT_NE(description.find("    quality FINAL\n"), std::string::npos) << description;
    EXPECT_NE(description.find("  ForeignNode\n    mode WEIRD\n    points [ ]\n"
                               "  TestCube \"cube\"\n    size 0.1\n"),
              std::string::npos)
        << description;
}

TEST_F(CoinInteropTest, coinRewritesOurFileIntoTheSameGraph) {
    const Node::Ptr scene = makeScene();
    WriteAction::writeFile(*scene, path("ours.iv"));
    runCoin("rewrite " + path("ours.iv") + " " + path("coin.iv"));
    const Node::Ptr reread = SceneReader::readFile(path("coin.iv"));
    EXPECT_EQ(graphDifference(*scene, *reread), "") << readText(path("coin.iv"));
}

TEST_F(CoinInteropTest, coinReadsEngineConnectionsToExtensionNodes) {
    const auto cube = TestCube::create();
    const auto time = ElapsedTime::create();
    time->speed.setValue(2.0f);
    time->reset.setValue(); // written as `reset` alone, which Coin reads (not `reset TRUE`)
    cube->size.connectFrom(time->timeOut);
    WriteAction::writeFile(*cube, path("ours.iv"));
    EXPECT_NE(readText(path("ours.iv")).find("        reset\n"), std::string::npos);
    EXPECT_EQ(runCoin("describe " + path("ours.iv")),
              "Separator\n  TestCube\n    size = ElapsedTime . timeOut\n        speed 2\n");
    runCoin("rewrite " + path("ours.iv") + " " + path("coin.iv"));
    const auto reread = std::dynamic_pointer_cast<Group>(SceneReader::readFile(path("coin.iv")));
    ASSERT_NE(reread, nullptr);
    const auto& follower = static_cast<const TestCube&>(*reread->child(0));
    ASSERT_NE(follower.size.connectedOutput(), nullptr);
    const auto& engine = static_cast<const ElapsedTime&>(follower.size.connectedOutput()->engine());
    EXPECT_EQ(engine.speed.value(), 2.0f);
}

TEST_F(CoinInteropTest, weReadWhatCoinWrites) {
    runCoin("sample " + path("coin.iv"));
    const auto root = std::dynamic_pointer_cast<Separator>(SceneReader::readFile(path("coin.iv")));
    ASSERT_NE(root, nullptr);
    EXPECT_EQ(root->renderCaching.as<CacheEnabled>(), CacheEnabled::Off);
    EXPECT_TRUE(root->boundingBoxCaching.isDefault());
    EXPECT_TRUE(root->renderCulling.isDefault());
    EXPECT_EQ(root->pickCulling.as<CacheEnabled>(), CacheEnabled::On);
    ASSERT_EQ(root->childCount(), 4u);
    const auto chooser = std::dynamic_pointer_cast<Switch>(root->child(0));
    ASSERT_NE(chooser, nullptr);
    EXPECT_EQ(chooser->name(), "chooser");
    EXPECT_EQ(chooser->whichChild.value(), 1);
    EXPECT_EQ(root->child(3), chooser);
    EXPECT_EQ(root->child(1), chooser->child(0));
    EXPECT_EQ(root->child(1)->name(), "");
    const auto& follower = static_cast<const Switch&>(*root->child(2));
    EXPECT_EQ(follower.whichChild.connectedField(), &chooser->whichChild);
    EXPECT_EQ(follower.whichChild.value(), 1);
}

} // namespace
