#include "scenegraph/io/SceneReader.h"

#include "SceneTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/Separator.h"
#include "scenegraph/Switch.h"
#include "scenegraph/io/UnknownNode.h"
#include "scenegraph/io/WriteAction.h"
#include "tests/scenegraph/TestFifo.h"

#include <gtest/gtest.h>

#include <clocale>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <locale>
#include <string>
#include <vector>

using namespace texsplat::sg;
using namespace texsplat::sg::test;
using texsplat::IoError;
using texsplat::ParseError;

namespace {

const std::string kHeader = "#Inventor V2.1 ascii\n";

class SceneReaderTest : public ::testing::Test {
protected:
    void SetUp() override { registerSceneTestTypes(); }

    static Node::Ptr read(const std::string& body) {
        return SceneReader::readString(kHeader + body, "scene.iv");
    }

    // The message of the ParseError that reading `text` (header included) throws.
    static std::string errorOf(const std::string& text) { return readError(text, "scene.iv"); }
};

template <class T> std::shared_ptr<T> as(const Node::Ptr& node) {
    auto typed = std::dynamic_pointer_cast<T>(node);
    EXPECT_NE(typed, nullptr);
    return typed;
}

TEST_F(SceneReaderTest, readsEveryFieldType) {
    const auto node = as<AllFields>(read(R"(
# a comment line
AllFields {   # a comment after a token
    flag FALSE
    count -2147483648
    size 2.5e-1
    label "say \"hi\" \\ bye"
    offset 1 2
    position -1 .5 3.
    color 0 0.5 1
    orientation 0 1 0 1.5707964
    matrix 1 0 0 0  0 1 0 0  0 0 1 0  4 5 6 1
    quality FINAL
    node TestCube { size 3 }
    indices [ 1, 0x10, -3 ]
    weights [ 0.25 0.75, ]
    points [ 1 2 3, 4 5 6 ]
    colors 1 0 0
    names [ "a b", plain ]
    nodes [ TestCube { }, NULL, Group { } ]
})"));
    EXPECT_FALSE(node->flag.value());
    EXPECT_EQ(node->count.value(), -2147483647 - 1);
    EXPECT_EQ(node->size.value(), 0.25f);
    EXPECT_EQ(node->label.value(), "say \"hi\" \\ bye");
    EXPECT_EQ(node->offset.value(), glm::vec2(1, 2));
    EXPECT_EQ(node->position.value(), glm::vec3(-1, 0.5f, 3));
    EXPECT_EQ(node->color.value(), glm::vec3(0, 0.5f, 1));
    EXPECT_EQ(node->orientation.value(), Rotation(glm::vec3(0, 1, 0), 1.5707964f));
    EXPECT_EQ(node->matrix.value()[3], glm::vec4(4, 5, 6, 1));
    EXPECT_EQ(node->quality.as<Quality>(), Quality::Final);
    EXPECT_EQ(as<TestCube>(node->node.value())->size.value(), 3.0f);
    EXPECT_EQ(node->indices.values(), (std::vector<std::int32_t>{1, 16, -3}));
    EXPECT_EQ(node->weights.values(), (std::vector<float>{0.25f, 0.75f}));
    EXPECT_EQ(node->points.values(), (std::vector<glm::vec3>{{1, 2, 3}, {4, 5, 6}}));
    EXPECT_EQ(node->colors.values(), (std::vector<glm::vec3>{{1, 0, 0}}));
    EXPECT_EQ(node->names.values(), (std::vector<std::string>{"a b", "plain"}));
    ASSERT_EQ(node->nodes.size(), 3u);
    EXPECT_EQ(node->nodes[0]->typeName(), "TestCube");
    EXPECT_EQ(node->nodes[1], nullptr);
    EXPECT_EQ(node->nodes[2]->typeName(), "Group");
}

TEST_F(SceneReaderTest, leavesUnmentionedFieldsAtTheirDefaults) {
    const auto node = as<AllFields>(read("AllFields { count 4 }"));
    EXPECT_FALSE(node->count.isDefault());
    EXPECT_TRUE(node->size.isDefault());
    EXPECT_EQ(node->size.value(), 1.6f);
}

TEST_F(SceneReaderTest, readsNonFiniteAndDenormalFloats) {
    const auto node = as<AllFields>(read("AllFields { weights [ inf, -inf, 1e-45, -0 ] }"));
    EXPECT_EQ(node->weights.valueText(), "[ inf, -inf, 1e-45, -0 ]");
    EXPECT_TRUE(std::isnan(as<TestCube>(read("TestCube { size nan }"))->size.value()));
}

TEST_F(SceneReaderTest, readsAndWritesNumbersTheSameInEveryLocale) {
    // An application may switch to a locale whose decimal separator is a comma.
    const std::string previousC = std::setlocale(LC_ALL, nullptr);
    const std::locale previous;
    const char* commaLocale = nullptr;
    for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "fr_FR.utf8", "de_DE",
                             "fr_FR"}) {
        if (std::setlocale(LC_ALL, name) != nullptr) {
            commaLocale = name;
            break;
        }
    }
    if (commaLocale == nullptr) {
        GTEST_SKIP() << "no comma-decimal locale (de_DE, fr_FR) is installed; `locale -a` lists "
                        "those there are";
    }
    std::locale::global(std::locale(commaLocale));
    struct Restore {
        const std::string& previousC;
        const std::locale& previous;
        ~Restore() {
            std::locale::global(previous);
            std::setlocale(LC_ALL, previousC.c_str());
        }
    } restore{previousC, previous};
    ASSERT_STREQ(std::localeconv()->decimal_point, ",");
    const auto node = as<AllFields>(read("AllFields { size 0.5 weights [ 1.25, -2e-3 ] }"));
    EXPECT_EQ(node->size.value(), 0.5f);
    EXPECT_EQ(node->weights.values(), (std::vector<float>{1.25f, -2e-3f}));
    const std::string text = WriteAction::writeString(*node);
    EXPECT_NE(text.find("size 0.5\n"), std::string::npos) << text;
    EXPECT_NE(text.find("weights [ 1.25, -0.002 ]\n"), std::string::npos) << text;
    EXPECT_EQ(errorOf(kHeader + "TestCube { size 1e39 }"),
              "scene.iv:2:17: number out of range for TestCube.size (SFFloat): '1e39' (largest "
              "float is 3.4028235e+38)");
}

TEST_F(SceneReaderTest, keepsSharedNodesShared) {
    const auto root = as<Separator>(read(R"(
Separator {
    DEF box TestCube { size 3 }
    Group { USE box }
    AllFields { node USE box nodes [ USE box, USE box ] }
})"));
    const Node::Ptr box = root->child(0);
    EXPECT_EQ(box->name(), "box");
    EXPECT_EQ(as<Group>(root->child(1))->child(0), box);
    const auto fields = as<AllFields>(root->child(2));
    EXPECT_EQ(fields->node.value(), box);
    EXPECT_EQ(fields->nodes[0], box);
    EXPECT_EQ(fields->nodes[1], box);
}

TEST_F(SceneReaderTest, stripsAutomaticDefNameSuffixes) {
    const auto root = as<Separator>(read("Separator { DEF +0 Group { } USE +0 "
                                         "DEF box+1 TestCube { } USE box+1 "
                                         "DEF _+2 Group { } DEF _ Group { } }"));
    ASSERT_EQ(root->childCount(), 6u);
    EXPECT_EQ(root->child(4)->name(), "");
    EXPECT_EQ(root->child(5)->name(), ""); // "_" is reserved for nodes without a name
    EXPECT_EQ(root->child(0)->name(), "");
    EXPECT_EQ(root->child(1), root->child(0));
    EXPECT_EQ(root->child(2)->name(), "box");
    EXPECT_EQ(root->child(3), root->child(2));
}

TEST_F(SceneReaderTest, laterDefinitionOfANameWins) {
    const auto root = as<Separator>(read(
        "Separator { DEF a TestCube { size 1 } DEF a TestCube { size 2 } USE a }"));
    EXPECT_EQ(root->child(2), root->child(1));
}

TEST_F(SceneReaderTest, connectsFieldsToEngineOutputs) {
    const auto cube = as<TestCube>(read("TestCube { size = DEF twice TestDoubler { input 2 } . output }"));
    ASSERT_NE(cube->size.connectedOutput(), nullptr);
    EXPECT_EQ(cube->size.value(), 4.0f);
    auto& doubler = static_cast<TestDoubler&>(cube->size.connectedOutput()->engine());
    EXPECT_EQ(doubler.name(), "twice");
    doubler.input.setValue(5.0f);
    EXPECT_EQ(cube->size.value(), 10.0f);
}

TEST_F(SceneReaderTest, connectsFieldsToFieldsWithOrWithoutAValue) {
    const auto root = as<Separator>(read(R"(
Separator {
    DEF a TestCube { size 5 }
    TestCube { size = USE a.size }
    TestCube { size 1 = USE a . size }
    DEF outer AllFields { size 2 TestCube { size = USE outer . size } }
})"));
    const auto a = as<TestCube>(root->child(0));
    const auto b = as<TestCube>(root->child(1));
    const auto c = as<TestCube>(root->child(2));
    EXPECT_EQ(b->size.value(), 5.0f);
    EXPECT_EQ(c->size.connectedField(), &a->size);
    a->size.setValue(7.0f);
    EXPECT_EQ(b->size.value(), 7.0f);
    EXPECT_EQ(c->size.value(), 7.0f);
    const auto outer = as<AllFields>(root->child(3));
    EXPECT_EQ(as<TestCube>(outer->child(0))->size.connectedField(), &outer->size);
}

TEST_F(SceneReaderTest, connectionsKeepSourcesThatNothingElseHolds) {
    // A source written in place, and one whose only holder is dropped from the scene when its
    // connection is replaced.
    const auto root = as<Separator>(read(R"(
Separator {
    TestCube { size = TestCube { size 3 } . size }
    TestCube {
        size = AllFields { DEF inner TestCube { size 4 } } . size
        size = USE inner . size
    }
})"));
    for (std::size_t i = 0; i < 2; ++i) {
        SCOPED_TRACE(i);
        SFFloat& size = as<TestCube>(root->child(i))->size;
        ASSERT_NE(size.connectedField(), nullptr);
        EXPECT_EQ(size.value(), 3.0f + static_cast<float>(i));
        static_cast<TestCube&>(*size.connectedField()->container()).size.setValue(8.0f);
        EXPECT_EQ(size.value(), 8.0f);
    }
}

TEST_F(SceneReaderTest, aConnectedNodeDroppedLaterInTheFileIsLeftOut) {
    // The first value of `node` has a connection and is replaced before the read ends (a
    // fuzzer finding: the connection outlived its field).
    const auto root = as<AllFields>(read(R"(
AllFields {
    node TestCube { size = TestCube { size 3 } . size }
    node NULL
    nodes [ Holder { fields [ SFFloat a ] a = TestCube { } . size } ]
    nodes [ ]
})"));
    EXPECT_EQ(root->node.value(), nullptr);
    EXPECT_EQ(root->nodes.size(), 0u);
}

TEST_F(SceneReaderTest, aSourceThatContainsItsTargetNeedsAnotherHolder) {
    const auto root = as<Separator>(read(
        "Separator { DEF t TestCube { size = DEF s AllFields { size 2 USE t } . size } USE s }"));
    const auto target = as<TestCube>(root->child(0));
    EXPECT_EQ(target->size.connectedField(), &as<AllFields>(root->child(1))->size);
    EXPECT_EQ(target->size.value(), 2.0f);
    // The inner source contains t1 too, but t1's own source is held by the scene: no cycle.
    const auto outer = as<Separator>(read("Separator { DEF t1 TestCube { size = DEF s1 AllFields { "
                                          "DEF t2 TestCube { size = AllFields { size 5 USE t1 } "
                                          ". size } } . size } USE s1 }"));
    const auto t2 = as<TestCube>(as<AllFields>(outer->child(1))->child(0));
    ASSERT_NE(t2->size.connectedField(), nullptr);
    EXPECT_EQ(t2->size.value(), 5.0f);
}

TEST_F(SceneReaderTest, putsSeveralTopLevelNodesUnderASeparator) {
    const auto root = as<Separator>(read("TestCube { } DEF g Group { } USE g"));
    ASSERT_EQ(root->childCount(), 3u);
    EXPECT_EQ(root->child(0)->typeName(), "TestCube");
    EXPECT_EQ(root->child(2), root->child(1));
}

TEST_F(SceneReaderTest, readsTheCoreNodesAndEngines) {
    const auto root = as<Switch>(read(
        "Switch { whichChild 1 Separator { } Group { TestCube { size = ElapsedTime { speed 2 } . timeOut } } }"));
    EXPECT_EQ(root->whichChild.value(), 1);
    ASSERT_EQ(root->childCount(), 2u);
    const auto cube = as<TestCube>(as<Group>(root->child(1))->child(0));
    ASSERT_NE(cube->size.connectedOutput(), nullptr);
    EXPECT_EQ(cube->size.connectedOutput()->engine().typeName(), "ElapsedTime");
}

TEST_F(SceneReaderTest, acceptsVersion20HeaderAndWindowsLineEnds) {
    EXPECT_EQ(SceneReader::readString("#Inventor V2.0 ascii\r\nGroup {\r\n}\r\n")->typeName(),
              "Group");
}

TEST_F(SceneReaderTest, readsAFile) {
    const Node::Ptr root = SceneReader::readFile(TEXSPLAT_TEST_DATA_DIR "/shared.iv");
    EXPECT_EQ(root->typeName(), "Separator");
}

TEST_F(SceneReaderTest, reportsAMissingFile) {
    try {
        SceneReader::readFile("/nonexistent/scene.iv");
        FAIL() << "no error";
    } catch (const IoError& error) {
        EXPECT_STREQ(error.what(),
                     "/nonexistent/scene.iv: cannot open scene file: No such file or directory");
    }
}

// The message of the IoError or ParseError that reading the file at `path` throws.
std::string fileError(const std::string& path) {
    try {
        SceneReader::readFile(path);
    } catch (const texsplat::Error& error) {
        return error.what();
    }
    return "no error";
}

std::string scratchPath(const std::string& name) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string path = ::testing::TempDir() + "SceneReaderTest_" + info->name() + "_" + name;
    std::filesystem::remove(path);
    return path;
}

TEST_F(SceneReaderTest, refusesFilesThatAreNotRegularBeforeOpeningThem) {
    // Reading a device never ends; opening a FIFO blocks until something writes to it.
    EXPECT_EQ(fileError("/dev/zero"),
              "/dev/zero: cannot read scene file: it is a character device, not a regular file");
    const texsplat::test::TestFifo pipe(scratchPath("scene.iv"));
    const std::string& fifo = pipe.path();
    EXPECT_EQ(fileError(fifo), fifo + ": cannot read scene file: it is a FIFO, not a regular file");
}

TEST_F(SceneReaderTest, aLoopOfSymbolicLinksIsAnIoErrorNamingTheFile) {
    // std::filesystem threw its own filesystem_error for it: "internal error".
    const std::string first = scratchPath("loop1.iv");
    const std::string second = scratchPath("loop2.iv");
    std::filesystem::create_symlink(second, first);
    std::filesystem::create_symlink(first, second);
    EXPECT_EQ(fileError(first),
              first + ": cannot read scene file: Too many levels of symbolic links");
    std::filesystem::remove(first);
    std::filesystem::remove(second);
}

// A scene of 100 MB of small nodes took 2.6 GB. What the file's nodes hold is counted as they
// are made and refused, at the line being read, where it passes the memory limit.
TEST_F(SceneReaderTest, aSceneAboveTheMemoryLimitIsRefusedWhereItPassesIt) {
    std::string text = "#Inventor V2.1 ascii\nSeparator {\n";
    for (int i = 0; i < 20000; ++i) {
        text += "  Group { }\n";
    }
    text += "}\n";
    const std::uint64_t limit = std::uint64_t{1} << 20;
    const std::uint64_t previous = texsplat::setMemoryLimit(limit);
    std::string message;
    try {
        SceneReader::readString(text, "big.iv");
    } catch (const texsplat::ResourceError& error) {
        message = error.what();
    }
    texsplat::setMemoryLimit(previous);
    // Where it stops depends on the nodes' sizes; that it stops inside the file does not.
    const std::size_t colon = message.find(':', 7);
    ASSERT_EQ(message.rfind("big.iv:", 0), 0u) << message;
    const int line = std::stoi(message.substr(7, colon - 7));
    EXPECT_GT(line, 100);
    EXPECT_LT(line, 20000);
    EXPECT_NE(message.find(": the scene read up to here (its text and the nodes made of it) "
                           "would need "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find(", more than the memory limit of 1048576 bytes (1 MiB); use a smaller "
                           "scene file, or a larger --memory-limit"),
              std::string::npos)
        << message;
    // Within the limit, the same text is read.
    EXPECT_EQ(SceneReader::readString(text, "big.iv")->typeName(), "Separator");
}

TEST_F(SceneReaderTest, checksTheHeaderBeforeReadingAHugeFile) {
    // A sparse 64 GiB file that starts like a PNG: refused from its first bytes, not read whole.
    const std::string path = scratchPath("huge.iv");
    std::ofstream(path, std::ios::binary) << "\x89PNG\r\n\x1a\n";
    std::filesystem::resize_file(path, std::uintmax_t{64} << 30);
    EXPECT_EQ(fileError(path),
              path + ":1:1: not an Inventor file: expected '#Inventor V2.1 ascii' on the first "
                     "line, got '\\x89PNG'");
    // A first line longer than the bytes checked is quoted the same way as from the whole text.
    std::ofstream(path, std::ios::binary | std::ios::trunc) << std::string(100000, 'x');
    EXPECT_EQ(fileError(path),
              path + ":1:1: not an Inventor file: expected '#Inventor V2.1 ascii' on the first "
                     "line, got '" + std::string(40, 'x') + "...'");
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        << "#Inventor V2.1 ascii" << std::string(1000, ' ') << "\nGroup { }";
    EXPECT_EQ(fileError(path), "no error");
    std::filesystem::remove(path);
}

TEST_F(SceneReaderTest, reportsEveryMalformedInputByLocationAndExpectation) {
    const std::string deep = [] {
        std::string text = kHeader;
        for (int i = 0; i < 1001; ++i) {
            text += "Group {\n";
        }
        return text;
    }();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"", "scene.iv:1:1: empty file, expected '#Inventor V2.1 ascii'"},
        {"#Inventor V2.1 binary\n\x01\x02",
         "scene.iv:1:1: binary Inventor files are not supported, expected '#Inventor V2.1 ascii'"},
        {"#VRML V2.0 utf8\nShape {}",
         "scene.iv:1:1: not an Inventor file: expected '#Inventor V2.1 ascii' on the first line, "
         "got '#VRML V2.0 utf8'"},
        {"\x89PNG\r\n\x1a\n",
         "scene.iv:1:1: not an Inventor file: expected '#Inventor V2.1 ascii' on the first line, "
         "got '\\x89PNG'"},
        {kHeader + "# nothing\n", "scene.iv:3:1: expected a node after the header, got end of file"},
        {kHeader + "Separator {\n  TestCube { }\n",
         "scene.iv:4:1: expected '}' to close Separator opened at 2:1"},
        {kHeader + "Group { Group { }", "scene.iv:2:18: expected '}' to close Group opened at 2:1"},
        {kHeader + "AllFields { label \"abc }\n",
         "scene.iv:3:1: expected '\"' to close the string opened at 2:19, got end of file"},
        {kHeader + "TestCube { sise 2 }",
         "scene.iv:2:12: unknown field 'sise' of TestCube (fields: size)"},
        {kHeader + "Group { size 2 }",
         "scene.iv:2:9: unknown field 'size' of Group (it has no fields)"},
        // Names echo the file's bytes as every message does: escaped, cut after 40 bytes.
        {kHeader + "Group { s\xc3\xafze 2 }",
         "scene.iv:2:9: unknown field 's\\xc3\\xafze' of Group (it has no fields)"},
        {kHeader + "USE cube\xff", "scene.iv:2:5: USE of undefined name 'cube\\xff'"},
        {kHeader + "TestCube { " + std::string(50, 'x') + " 2 }",
         "scene.iv:2:12: unknown field '" + std::string(40, 'x') +
             "...' of TestCube (fields: size)"},
        {kHeader + "TestCube { size abc }",
         "scene.iv:2:17: expected a number for TestCube.size (SFFloat), got 'abc'"},
        {kHeader + "TestCube { size 1.5.2 }",
         "scene.iv:2:17: expected a number for TestCube.size (SFFloat), got '1.5.2'"},
        {kHeader + "AllFields { position 1 2 }",
         "scene.iv:2:26: expected a number for AllFields.position (SFVec3f), got '}'"},
        {kHeader + "AllFields { position 1 2 3 4 }",
         "scene.iv:2:28: too many values for AllFields.position (SFVec3f), got '4'"},
        {kHeader + "AllFields { label \"a\" \"b\" }",
         "scene.iv:2:23: too many values for AllFields.label (SFString), got '\"b\"'"},
        {kHeader + "AllFields { flag TRUE FALSE }",
         "scene.iv:2:23: too many values for AllFields.flag (SFBool), got 'FALSE'"},
        {kHeader + "AllFields { quality FINAL DRAFT }",
         "scene.iv:2:27: too many values for AllFields.quality (SFEnum), got 'DRAFT'"},
        {kHeader + "AllFields { names \"a\" \"b c\" }",
         "scene.iv:2:23: too many values for AllFields.names (MFString), got '\"b c\"' (put "
         "several values in [ ])"},
        {kHeader + "AllFields { weights 1 2 }",
         "scene.iv:2:23: too many values for AllFields.weights (MFFloat), got '2' "
         "(put several values in [ ])"},
        {kHeader + "AllFields { count 1.5 }",
         "scene.iv:2:19: expected an integer for AllFields.count (SFInt32), got '1.5'"},
        {kHeader + "AllFields { count 2147483648 }",
         "scene.iv:2:19: integer out of range for AllFields.count (SFInt32): '2147483648' "
         "(expected -2147483648 to 2147483647)"},
        {kHeader + "AllFields { indices [ 0, -2147483649 ] }",
         "scene.iv:2:26: integer out of range for AllFields.indices (MFInt32): '-2147483649' "
         "(expected -2147483648 to 2147483647)"},
        {kHeader + "TestCube { size 1e39 }",
         "scene.iv:2:17: number out of range for TestCube.size (SFFloat): '1e39' "
         "(largest float is 3.4028235e+38)"},
        {kHeader + "AllFields { flag maybe }", "scene.iv:2:18: expected TRUE or FALSE, got 'maybe'"},
        {kHeader + "AllFields { quality BEST }",
         "scene.iv:2:21: unknown value 'BEST' for SFEnum AllFields.quality (expected one of "
         "DRAFT, FINAL)"},
        {kHeader + "AllFields { weights [ 1, 2",
         "scene.iv:2:27: expected ']' to close the list opened at 2:21, got end of file"},
        {kHeader + "AllFields { nodes [ Group { }",
         "scene.iv:2:30: expected ']' to close the list opened at 2:19, got end of file"},
        {kHeader + "Separator { USE nothing }", "scene.iv:2:17: USE of undefined name 'nothing'"},
        {kHeader + "Foo { }",
         "scene.iv:2:1: unknown node type 'Foo' (not registered, and no 'fields [ ... ]' "
         "description follows)"},
        {kHeader + "Foo { fields [ SFImage picture ] }",
         "scene.iv:2:16: unknown field type 'SFImage' for field 'picture' of Foo"},
        {kHeader + "Foo { fields [ SFFloat a, SFInt32 a ] }",
         "scene.iv:2:27: field 'a' of Foo is described twice"},
        {kHeader + "Foo { fields [ SFFloat a",
         "scene.iv:2:25: expected ']' to close the fields description opened at 2:14, got end of "
         "file"},
        {kHeader + "TestCube { fields [ SFInt32 size ] }",
         "scene.iv:2:21: field 'size' of TestCube is SFFloat, but the description says SFInt32"},
        {kHeader + "TestCube { fields [ SFFloat width ] }",
         "scene.iv:2:21: TestCube has no field 'width' (described as SFFloat)"},
        {deep, "scene.iv:1002:1: nodes nested deeper than the limit of 1000 levels"},
        {kHeader + "Group { \x01 }", "scene.iv:2:9: unexpected control character '\\x01'"},
        {kHeader + "Group { " + std::string(1, '\0') + " }",
         "scene.iv:2:9: unexpected control character '\\x00' (binary data?)"},
        {kHeader + "Separator { TestDoubler { } }",
         "scene.iv:2:13: expected a node, got engine TestDoubler (engines appear only in "
         "connections: field = Engine { } . output)"},
        {kHeader + "TestCube { Group { } }",
         "scene.iv:2:12: TestCube cannot have children, got 'Group' (only groups such as "
         "Separator can)"},
        {kHeader + "Group Group", "scene.iv:2:7: expected '{' after Group, got 'Group'"},
        {kHeader + "Group { [ }",
         "scene.iv:2:9: expected a field name, a child node or '}' in Group, got '['"},
        {kHeader + "NULL", "scene.iv:2:1: expected a node, got 'NULL' at the top level"},
        {kHeader + "1.5", "scene.iv:2:1: expected a node type name, got '1'"},
        {kHeader + "DEF 3d Group { }",
         "scene.iv:2:8: Group: invalid name '3d' (a name must not start with a digit or '#' "
         "and must not contain whitespace, control characters or any of \"'+,.[\\]{})"},
        {kHeader + "TestCube { size = TestDoubler { } }",
         "scene.iv:2:35: expected '.' and a field or output name after the source of the "
         "connection to TestCube.size, got '}'"},
        {kHeader + "TestCube { size = TestDoubler { } . nothing }",
         "scene.iv:2:37: TestDoubler has no field or output 'nothing'"},
        {kHeader + "DEF a TestCube { size = USE a . size }",
         "scene.iv:2:33: cannot connect SFFloat TestCube(a).size from SFFloat TestCube(a).size: "
         "connection cycle TestCube(a).size <- TestCube(a).size"},
        {kHeader + "DEF a TestCube { size = DEF b TestCube { size = USE a . size } . size }",
         "scene.iv:2:66: cannot connect SFFloat TestCube(a).size from SFFloat TestCube(b).size: "
         "connection cycle TestCube(a).size <- TestCube(b).size <- TestCube(a).size"},
        {kHeader + "DEF t TestCube { size = AllFields { USE t } . size }",
         "scene.iv:2:25: cannot keep AllFields alive as the source of TestCube(t).size: it "
         "contains TestCube(t) (directly or through others), and nothing else in the scene "
         "holds it"},
        {kHeader + "TestCube { size = Bar { inputs [ SFFloat a ] outputs [ SFFloat b ] } . b }",
         "scene.iv:2:19: unknown engine type 'Bar' (engines must be registered to be read)"},
    };
    for (const auto& [text, message] : cases) {
        SCOPED_TRACE(text.substr(0, 80));
        EXPECT_EQ(errorOf(text), message);
    }
}

TEST_F(SceneReaderTest, reportsGraphErrorsAtTheirLocation) {
    EXPECT_EQ(errorOf(kHeader + "DEF a Group { USE a }").substr(0, 14), "scene.iv:2:15:");
    EXPECT_EQ(errorOf(kHeader + "AllFields { count = TestDoubler { } . output }").substr(0, 14),
              "scene.iv:2:39:");
}

} // namespace
