// The scenes of docs/transfer-functions.md read and their transfer functions are valid, so the
// page cannot rot (scripts/transfer-function-pictures.sh renders them into its pictures).

#include "nodes/NodeTypes.h"
#include "nodes/TransferFunction.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

// The fenced blocks of `markdown` that are scene files (start with the Inventor header).
std::vector<std::string> sceneBlocks(const std::string& markdown) {
    std::vector<std::string> scenes;
    std::istringstream lines(markdown);
    std::string line;
    std::string block;
    bool isInside = false;
    while (std::getline(lines, line)) {
        if (line.rfind("```", 0) == 0) {
            if (isInside && block.rfind("#Inventor V2.1 ascii\n", 0) == 0) {
                scenes.push_back(block);
            }
            isInside = !isInside;
            block.clear();
        } else if (isInside) {
            block += line + "\n";
        }
    }
    return scenes;
}

TEST(TransferFunctionDocs, theScenesOfThePageAreValid) {
    registerNodeTypes();
    std::ifstream file(TEXSPLAT_SOURCE_DIR "/docs/transfer-functions.md");
    ASSERT_TRUE(file);
    std::stringstream text;
    text << file.rdbuf();
    const std::vector<std::string> scenes = sceneBlocks(text.str());
    EXPECT_GE(scenes.size(), 4U);
    for (const std::string& scene : scenes) {
        const sg::Node::Ptr root = sg::SceneReader::readString(scene, "transfer-functions.md");
        sg::SearchAction search;
        search.setType(TransferFunction::classType());
        search.apply(*root);
        ASSERT_EQ(search.paths().size(), 1U) << scene;
        EXPECT_NO_THROW(
            std::static_pointer_cast<TransferFunction>(search.paths().front().tail())->validate())
            << scene;
    }
}

} // namespace
} // namespace texsplat::nodes
