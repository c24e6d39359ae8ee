#include "scenegraph/io/WriteAction.h"

#include "SceneTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/Separator.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/UnknownNode.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

using namespace texsplat::sg;
using namespace texsplat::sg::test;

namespace {

class WriteActionTest : public ::testing::Test {
protected:
    void SetUp() override { registerSceneTestTypes(); }

    // Writes `root`, reads the text back, and checks that the graph and its text survive.
    static void expectRoundTrip(Node& root) {
        const std::string text = WriteAction::writeString(root);
        const Node::Ptr copy = SceneReader::readString(text, "written.iv");
        EXPECT_EQ(graphDifference(root, *copy), "") << text;
        EXPECT_EQ(WriteAction::writeString(*copy), text);
    }

    // read → write → read gives the same graph, starting from what `root` writes. Unlike
    // expectRoundTrip() this allows a type to keep a field default on purpose (ElapsedTime's
    // timeIn, the clock's reading, is never written).
    static void expectReadWriteRead(Node& root) {
        const Node::Ptr first = SceneReader::readString(WriteAction::writeString(root));
        const std::string text = WriteAction::writeString(*first);
        const Node::Ptr second = SceneReader::readString(text, "written.iv");
        EXPECT_EQ(graphDifference(*first, *second), "") << text;
        EXPECT_EQ(WriteAction::writeString(*second), text);
    }
};

TEST_F(WriteActionTest, writesOnlyFieldsThatAreNotDefault) {
    const auto root = Separator::create();
    const auto cube = TestCube::create();
    cube->size.setValue(3.0f);
    root->addChild(cube);
    root->addChild(TestCube::create());
    EXPECT_EQ(WriteAction::writeString(*root), R"(#Inventor V2.1 ascii

Separator {
    TestCube {
        fields [ SFFloat size ]
        size 3
    }
    TestCube {
        fields [ SFFloat size ]
    }
}
)");
}

TEST_F(WriteActionTest, namesSharedNodesOnceAndUsesThemAfterwards) {
    const auto root = Separator::create();
    const auto shared = Group::create();
    const auto named = Group::create();
    named->setName("box");
    const auto sameName = Group::create();
    sameName->setName("box");
    for (const Node::Ptr& child : {Node::Ptr(shared), Node::Ptr(named), Node::Ptr(sameName),
                                   Node::Ptr(shared), Node::Ptr(sameName)}) {
        root->addChild(child);
    }
    EXPECT_EQ(WriteAction::writeString(*root), R"(#Inventor V2.1 ascii

Separator {
    DEF +0 Group {
    }
    DEF box Group {
    }
    DEF box+1 Group {
    }
    USE +0
    USE box+1
}
)");
    expectRoundTrip(*root);
}

TEST_F(WriteActionTest, writesConnectionsInline) {
    const auto root = Separator::create();
    const auto source = TestCube::create();
    const auto follower = TestCube::create();
    const auto doubler = TestDoubler::create();
    doubler->input.setValue(2.0f);
    source->size.connectFrom(doubler->output);
    follower->size.connectFrom(source->size);
    root->addChild(follower);
    root->addChild(source);
    EXPECT_EQ(WriteAction::writeString(*root), R"(#Inventor V2.1 ascii

Separator {
    TestCube {
        fields [ SFFloat size ]
        size = DEF +0 TestCube {
            fields [ SFFloat size ]
            size = TestDoubler {
                inputs [ SFFloat input ]
                outputs [ SFFloat output ]
                input 2
            } . output
        } . size
    }
    USE +0
}
)");
    expectRoundTrip(*root);
}

TEST_F(WriteActionTest, keepsConnectionsFromSourcesOutsideTheScene) {
    // The source is not in the scene: it is written in place, and the connection read back
    // holds it (here, the test holds it).
    const auto source = TestCube::create();
    source->size.setValue(3.0f);
    const auto follower = TestCube::create();
    follower->size.connectFrom(source->size);
    EXPECT_EQ(WriteAction::writeString(*follower), R"(#Inventor V2.1 ascii

TestCube {
    fields [ SFFloat size ]
    size = TestCube {
        fields [ SFFloat size ]
        size 3
    } . size
}
)");
    expectRoundTrip(*follower);
    expectReadWriteRead(*follower);
    const Node::Ptr copy = SceneReader::readString(
        "#Inventor V2.1 ascii\nTestCube { size = TestCube { size 3 } . size }");
    EXPECT_EQ(graphDifference(*follower, *copy), "");
}

TEST_F(WriteActionTest, writesEveryNameThatNodesAcceptSoThatItReadsBack) {
    const auto root = Separator::create();
    for (const char* name : {"_a", "a_", "a#b", "box_1-a", "a=b", "a|b", "a/b", "a(1)", "a~!@$%^&*?<>;:`",
                             "NULL", "USE", "DEF", "fields", "\xc3\xa9t\xc3\xa9"}) {
        SCOPED_TRACE(name);
        const auto named = TestCube::create();
        named->setName(name);
        const auto follower = TestCube::create();
        follower->size.connectFrom(named->size);
        root->addChild(named);
        root->addChild(follower);
        root->addChild(named);
    }
    expectRoundTrip(*root);
}

TEST_F(WriteActionTest, writesNodeListsOneNodePerLine) {
    const auto fields = AllFields::create();
    const auto inner = AllFields::create();
    inner->weights.setValue({1.0f, 2.0f});
    fields->nodes.setValue({inner, nullptr});
    fields->node.setValue(TestCube::create());
    const std::string text = WriteAction::writeString(*fields);
    EXPECT_NE(text.find(R"(
    node TestCube {
        fields [ SFFloat size ]
    }
    nodes [
        AllFields {
)"), std::string::npos) << text;
    EXPECT_NE(text.find(R"(
            weights [ 1, 2 ]
        }
        NULL
    ]
}
)"), std::string::npos) << text;
    expectRoundTrip(*fields);
}

TEST_F(WriteActionTest, roundTripsEveryFieldType) {
    const auto root = AllFields::create();
    root->setName("all");
    const auto cube = TestCube::create();
    root->flag.setValue(false);
    root->count.setValue(-2147483647 - 1);
    root->size.setValue(0.1f);
    root->label.setValue("quote \" backslash \\ newline \n end");
    root->offset.setValue({1e-45f, -0.0f});
    root->position.setValue({3.4028235e38f, -1.0f, 1.0f / 3.0f});
    root->color.setValue({0.2f, 0.4f, 0.6f});
    root->orientation.setValue(Rotation({0.0f, 1.0f, 0.0f}, 3.14159274f));
    root->matrix.setValue(glm::mat4(2.0f));
    root->quality.setValue(Quality::Final);
    root->node.setValue(cube);
    root->indices.setValue({1, -2, 2147483647});
    root->weights.setValue({});
    root->points.setValue(std::vector<glm::vec3>(40, glm::vec3(0.125f, 1e10f, -7.0f)));
    root->colors.setValue({{1.0f, 0.0f, 0.0f}});
    root->names.setValue({"", "two words", "#not a comment"});
    root->nodes.setValue({cube, nullptr, Separator::create()});
    root->addChild(cube);
    expectRoundTrip(*root);
}

TEST_F(WriteActionTest, roundTripsEveryRegisteredType) {
    for (const NodeType* type : NodeRegistry::instance().types()) {
        SCOPED_TRACE(type->name());
        if (type->isAbstract()) {
            continue;
        }
        const std::shared_ptr<FieldContainer> instance = type->create();
        // Written with every field: each default value must read back as itself.
        for (Field* field : instance->fields()) {
            field->setDefault(false);
        }
        if (Node* node = instance->asNode()) {
            expectReadWriteRead(*node);
            continue;
        }
        // An engine is written where a field connects from it: one per output.
        const auto& engine = static_cast<const Engine&>(*instance);
        const UnknownNode::Ptr holder = UnknownNode::create("Holder");
        for (EngineOutputBase* output : engine.outputs()) {
            holder->addDescribedField(output->typeName(), output->name()).connectFrom(*output);
        }
        expectReadWriteRead(*holder);
    }
}

TEST_F(WriteActionTest, wrapsLongListsAndReadsThemBack) {
    const auto fields = AllFields::create();
    fields->weights.setValue(std::vector<float>(100, 0.123456789f));
    const std::string text = WriteAction::writeString(*fields);
    std::size_t lineStart = 0;
    for (std::size_t end = text.find('\n'); end != std::string::npos;
         lineStart = end + 1, end = text.find('\n', lineStart)) {
        EXPECT_LE(end - lineStart, 100u);
    }
    expectRoundTrip(*fields);
}

TEST_F(WriteActionTest, writesAFileAtomically) {
    const std::filesystem::path directory =
        std::filesystem::path(::testing::TempDir()) / ("texsplat_write_" + std::to_string(getpid()));
    std::filesystem::create_directories(directory);
    const std::string path = (directory / "scene.iv").string();
    const auto cube = TestCube::create();
    cube->size.setValue(7.0f);
    WriteAction::writeFile(*cube, path);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory),
                            std::filesystem::directory_iterator()),
              1);
    EXPECT_EQ(graphDifference(*cube, *SceneReader::readFile(path)), "");
    std::filesystem::remove_all(directory);
    EXPECT_THROW(WriteAction::writeFile(*cube, path), texsplat::IoError);
}

} // namespace
