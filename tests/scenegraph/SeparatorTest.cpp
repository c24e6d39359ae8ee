#include "scenegraph/Separator.h"

#include "TestNodes.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace texsplat::sg {
namespace {

using test::TestCube;
using test::TestTranslation;

TestTranslation::Ptr translation(const glm::vec3& offset) {
    TestTranslation::Ptr node = TestTranslation::create();
    node->translation = offset;
    return node;
}

TEST(Separator, restoresTheStateForItsSiblings) {
    // Separator { Translation 10 0 0  Cube }  Cube: the second cube is not moved.
    Group::Ptr root = Group::create();
    Separator::Ptr separator = Separator::create();
    separator->addChild(translation(glm::vec3(10.0f, 0.0f, 0.0f)));
    separator->addChild(TestCube::create());
    root->addChild(separator);
    root->addChild(TestCube::create());
    BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(), Box3(glm::vec3(-1.0f), glm::vec3(11.0f, 1.0f, 1.0f)));
    EXPECT_EQ(action.state().depth(), 0u);
}

TEST(Separator, aGroupDoesNotRestore) {
    Group::Ptr root = Group::create();
    Group::Ptr group = Group::create();
    group->addChild(translation(glm::vec3(10.0f, 0.0f, 0.0f)));
    root->addChild(group);
    root->addChild(TestCube::create());
    BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(),
        Box3(glm::vec3(9.0f, -1.0f, -1.0f), glm::vec3(11.0f, 1.0f, 1.0f)));
}

TEST(Separator, isRegisteredAsAGroup) {
    Separator::Ptr separator = Separator::create();
    EXPECT_EQ(separator->typeName(), "Separator");
    EXPECT_TRUE(separator->type().isDerivedFrom(Group::classType()));
}

// Inventor's caching and culling hints: read and written (Coin writes them), not used.
TEST(Separator, readsAndWritesInventorsCachingFields) {
    const Separator::Ptr separator = Separator::create();
    std::vector<std::string> names;
    for (const Field* field : separator->fields()) {
        names.push_back(field->name() + " " + field->valueText());
    }
    EXPECT_EQ(names, (std::vector<std::string>{"renderCaching AUTO", "boundingBoxCaching AUTO",
                                               "renderCulling AUTO", "pickCulling AUTO"}));
    const std::string text = "#Inventor V2.1 ascii\n\nSeparator {\n    renderCaching OFF\n"
                             "    boundingBoxCaching ON\n    renderCulling OFF\n"
                             "    pickCulling ON\n}\n";
    const auto read = std::dynamic_pointer_cast<Separator>(SceneReader::readString(text));
    ASSERT_NE(read, nullptr);
    EXPECT_EQ(read->renderCaching.as<CacheEnabled>(), CacheEnabled::Off);
    EXPECT_EQ(read->boundingBoxCaching.as<CacheEnabled>(), CacheEnabled::On);
    EXPECT_EQ(read->renderCulling.as<CacheEnabled>(), CacheEnabled::Off);
    EXPECT_EQ(read->pickCulling.as<CacheEnabled>(), CacheEnabled::On);
    EXPECT_EQ(WriteAction::writeString(*read), text);
}

} // namespace
} // namespace texsplat::sg
