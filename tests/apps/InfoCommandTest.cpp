#include "RunCommand.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <unistd.h>

namespace fs = std::filesystem;
using texsplat::test::runTexsplat;

namespace {

class InfoCommandTest : public texsplat::test::ScratchDirectoryTest {};

TEST_F(InfoCommandTest, printsTheGraphWithItsNonDefaultFields) {
    const std::string path = write("scene.iv", R"(#Inventor V2.1 ascii
Separator {
    DEF pick Switch { whichChild 0 Group { } }
    Switch { whichChild = USE pick . whichChild }
    USE pick
}
)");
    const auto output = runTexsplat("info " + path);
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_EQ(output.standardOutput, "#Inventor V2.1 ascii\n# " + path + R"(: 4 nodes, 0 engines, 1 shared; Group 1, Separator 1, Switch 2

Separator {
    DEF pick Switch {
        whichChild 0
        Group {
        }
    }
    Switch {
        whichChild = USE pick . whichChild
    }
    USE pick
}
)");
}

TEST_F(InfoCommandTest, printsTheReadErrorWithFileLineAndColumn) {
    const std::string path = write("bad.iv", "#Inventor V2.1 ascii\nSwitch { whichChil 1 }\n");
    const auto output = runTexsplat("info " + path);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardOutput, "");
    EXPECT_EQ(output.standardError, "texsplat: error: " + path +
                                        ":2:10: unknown field 'whichChil' of Switch (fields: "
                                        "whichChild)\n");
}

// Usage errors are CLI11's: its message first, its exit code (not 0, not kExitFailure).
TEST_F(InfoCommandTest, needsASceneOrTheReference) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"info", "scene (or --reference) is required\n"},
        {"info --reference scene.iv", "scene excludes --reference\n"},
        {"info --update x.md", "--update requires --reference\n"},
    };
    for (const auto& [arguments, message] : cases) {
        const auto output = runTexsplat(arguments);
        EXPECT_NE(output.exitCode, 0) << arguments;
        EXPECT_NE(output.exitCode, 1) << arguments;
        EXPECT_EQ(output.standardError.substr(0, message.size()), message) << arguments;
    }
}

TEST_F(InfoCommandTest, readsEveryExampleSceneWithTheNodesLibrarysTypes) {
    for (const char* name : {"tornado", "marschner-lobb", "blob", "jet-stream", "aerogel"}) {
        const auto output =
            runTexsplat("info " TEXSPLAT_SOURCE_DIR "/examples/" + std::string(name) + ".iv");
        EXPECT_EQ(output.exitCode, 0) << name << ": " << output.standardError;
        EXPECT_NE(output.standardOutput.find("VolumeData {"), std::string::npos) << name;
    }
}

TEST_F(InfoCommandTest, referenceListsTypesWithFieldsAndDefaults) {
    const auto output = runTexsplat("info --reference");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardOutput.find(R"(### Switch

Node, derived from Group. Takes child nodes. Standard Inventor type.

| field | type | default |
|---|---|---|
| whichChild | SFInt32 | `-1` |
)"),
              std::string::npos)
        << output.standardOutput;
}

TEST_F(InfoCommandTest, docsHoldTheCurrentGeneratedReference) {
    const std::string docs = read(TEXSPLAT_SOURCE_DIR "/docs/scene-files.md");
    const std::string copy = write("scene-files.md", docs);
    const auto output = runTexsplat("info --reference --update " + copy);
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_TRUE(read(copy) == docs)
        << "docs/scene-files.md is out of date: run `texsplat info --reference --update "
           "docs/scene-files.md`";
}

TEST_F(InfoCommandTest, updateNeedsTheGeneratedSectionMarkers) {
    const std::string path = write("plain.md", "# no markers\n");
    const auto output = runTexsplat("info --reference --update " + path);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError,
              "texsplat: error: " + path +
                  ": expected the lines '<!-- BEGIN GENERATED REFERENCE (texsplat info "
                  "--reference): do not edit by hand -->' and then '<!-- END GENERATED "
                  "REFERENCE -->' around the generated reference\n");
    EXPECT_EQ(read(path), "# no markers\n");
}

} // namespace
