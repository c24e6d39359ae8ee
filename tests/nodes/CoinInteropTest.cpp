// Coin3D and texsplat agree on the standard nodes texsplat has (cameras, Transform, Material,
// DirectionalLight, Coordinate3, IndexedFaceSet, and the core's Separator, Group, Switch and
// ElapsedTime): the same fields, each read by the other with the same values. coin_interop_tool
// (tests/scenegraph/CoinInteropTool.cpp) is the Coin side.

#include "nodes/NodeTypes.h"

#include "nodes/Camera.h"
#include "nodes/DirectionalLight.h"
#include "nodes/Material.h"
#include "nodes/VectorMarkSplat.h"
#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/Separator.h"
#include "scenegraph/engines/ElapsedTime.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"
#include "tests/scenegraph/CoinInteropSupport.h"
#include "tests/scenegraph/FieldSamples.h"
#include "tests/scenegraph/SceneTestSupport.h"

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

using sg::test::describeFieldDeclarations;
using sg::test::describeScene;
using sg::test::descriptionDifference;

class CoinInteropTest : public sg::test::CoinInteropFixture {
protected:
    void SetUp() override {
        CoinInteropFixture::SetUp();
        registerNodeTypes();
        sg::registerEngineTypes(sg::NodeRegistry::instance());
    }

    // The registered types Coin knows, each with Coin's field declarations (the tool's `fields`
    // format); extension types are left out.
    std::map<std::string, std::string> coinDeclarations() const {
        std::string names;
        for (const sg::NodeType* type : sg::NodeRegistry::instance().types()) {
            if (!type->isAbstract()) {
                names += " " + type->name();
            }
        }
        std::istringstream lines(runCoin("fields" + names));
        std::map<std::string, std::string> declarations;
        std::string* current = nullptr;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("  ", 0) == 0) {
                *current += line + "\n";
            } else if (line.find(" unknown") == std::string::npos) {
                current = &declarations[line];
                *current = line + "\n";
            }
        }
        return declarations;
    }
};

// Reads `text` (the tool's `fields` format, one type) into "name" -> "TYPE DEFAULT", outputs as
// "output name" -> "TYPE".
std::map<std::string, std::string> fieldsByName(const std::string& text) {
    std::map<std::string, std::string> fields;
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line); // the type name
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string first;
        std::string second;
        words >> first >> second;
        std::string rest;
        std::getline(words, rest);
        if (first == "output") {
            fields["output " + rest.substr(1)] = second;
        } else {
            fields[second] = first + rest;
        }
    }
    return fields;
}

// Our declarations of the standard types against Coin's: same field names, types and defaults
// (numbers to float precision). What is left is listed here and in docs/scene-files.md.
TEST_F(CoinInteropTest, standardTypesDeclareCoinsFields) {
    std::vector<std::string> compared;
    std::vector<std::string> differences;
    for (const auto& [name, coinText] : coinDeclarations()) {
        compared.push_back(name);
        const auto ours = fieldsByName(
            describeFieldDeclarations(*sg::NodeRegistry::instance().create(name)));
        const auto coin = fieldsByName(coinText);
        for (const auto& [field, coinValue] : coin) {
            const auto found = ours.find(field);
            if (found == ours.end()) {
                differences.push_back(name + "." + field + ": Coin " + coinValue +
                                      ", texsplat none");
            } else if (!descriptionDifference(coinValue, found->second).empty()) {
                differences.push_back(name + "." + field + ": Coin " + coinValue + ", texsplat " +
                                      found->second);
            }
        }
        for (const auto& [field, ourValue] : ours) {
            if (coin.count(field) == 0) {
                differences.push_back(name + "." + field + ": Coin none, texsplat " + ourValue);
            }
        }
    }
    EXPECT_EQ(compared, (std::vector<std::string>{
                            "Coordinate3", "DirectionalLight", "ElapsedTime", "Group",
                            "IndexedFaceSet", "Material", "OrthographicCamera",
                            "PerspectiveCamera", "Separator", "Switch", "Transform"}));
    EXPECT_EQ(differences,
              (std::vector<std::string>{
                  "ElapsedTime.output timeOut: Coin SFTime, texsplat SFFloat",
                  "ElapsedTime.timeIn: Coin SFTime connected, texsplat SFFloat 0",
                  "IndexedFaceSet.coordIndex: Coin MFInt32 0, texsplat MFInt32 []",
                  "IndexedFaceSet.vertexProperty: Coin SFNode NULL, texsplat none"}));
}

// Coin writes every standard node texsplat has with every field set (lists of several values,
// an ElapsedTime driving a light); we read the same values.
TEST_F(CoinInteropTest, weReadEveryFieldCoinWritesForTheStandardNodes) {
    runCoin("standard " + path("coin.iv"));
    const std::string coinDescription = runCoin("describe " + path("coin.iv"));
    const sg::Node::Ptr root = sg::SceneReader::readFile(path("coin.iv"));
    EXPECT_EQ(descriptionDifference(coinDescription, describeScene(*root)), "")
        << coinDescription << "\n" << describeScene(*root);

    const auto& separator = dynamic_cast<const sg::Separator&>(*root);
    EXPECT_EQ(separator.renderCaching.as<sg::CacheEnabled>(), sg::CacheEnabled::Off);
    ASSERT_EQ(separator.childCount(), 7u);
    const auto& material = dynamic_cast<const Material&>(*separator.child(3));
    EXPECT_EQ(material.diffuseColor.values(),
              (std::vector<glm::vec3>{{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}));
    EXPECT_EQ(material.transparency.values(), (std::vector<float>{0.25f, 0.5f, 0.75f}));
    const auto& light = dynamic_cast<const DirectionalLight&>(*separator.child(4));
    ASSERT_NE(light.intensity.connectedOutput(), nullptr);
    const auto& time =
        dynamic_cast<const sg::ElapsedTime&>(light.intensity.connectedOutput()->engine());
    EXPECT_EQ(time.speed.value(), 2.0f);
    EXPECT_FALSE(time.reset.isDefault()); // Coin wrote `reset` alone: read as the trigger firing
}

// Our writer writes one node of every standard type with every field at a value that is not its
// default (and an ElapsedTime driving a field); Coin reads the same values, and what Coin writes
// back reads into the same graph.
TEST_F(CoinInteropTest, coinReadsEveryFieldWeWriteForTheStandardNodes) {
    const auto root = sg::Separator::create();
    std::vector<sg::FieldContainer::Ptr> engines;
    for (const auto& [name, declarations] : coinDeclarations()) {
        const sg::NodeType& type = *sg::NodeRegistry::instance().find(name);
        const sg::Node::Ptr read = sg::SceneReader::readString(sg::test::sampleSceneText(type));
        if (read->typeName() == name) {
            root->addChild(read);
        } else {
            // An engine, read as the source of a connection into a Holder node.
            sg::Engine& engine = read->fields().front()->connectedOutput()->engine();
            engines.push_back(engine.shared_from_this());
        }
    }
    // Each engine drives the first field of its output's type.
    for (const sg::FieldContainer::Ptr& container : engines) {
        sg::EngineOutputBase& output = *static_cast<sg::Engine&>(*container).outputs().front();
        bool isConnected = false;
        for (const sg::Node::Ptr& child : root->children()) {
            for (sg::Field* field : child->fields()) {
                if (!isConnected && field->typeName() == output.typeName()) {
                    field->connectFrom(output);
                    isConnected = true;
                }
            }
        }
        EXPECT_TRUE(isConnected) << container->typeName();
    }
    sg::WriteAction::writeFile(*root, path("ours.iv"));
    const std::string coinDescription = runCoin("describe " + path("ours.iv"));
    EXPECT_EQ(descriptionDifference(coinDescription, describeScene(*root)), "")
        << coinDescription << "\n" << describeScene(*root);

    // Coin reads a fired trigger (`reset`) but does not keep it fired; compare without.
    for (const sg::FieldContainer::Ptr& engine : engines) {
        for (sg::Field* field : engine->fields()) {
            if (field->typeName() == "SFTrigger") {
                field->setDefault(true);
            }
        }
    }
    sg::WriteAction::writeFile(*root, path("ours.iv"));
    runCoin("rewrite " + path("ours.iv") + " " + path("coin.iv"));
    EXPECT_EQ(sg::test::graphDifference(*root, *sg::SceneReader::readFile(path("coin.iv"))), "")
        << readText(path("coin.iv"));
}

// Coin writes a connected field's value with its connection (`phase 0 = ElapsedTime ...`),
// which reads back as a value that was set: mark the phases of `node`'s subtree so.
void markPhasesSet(sg::Node& node) {
    if (auto* splat = dynamic_cast<VectorMarkSplat*>(&node)) {
        splat->phase.setDefault(false);
    }
    if (auto* group = dynamic_cast<sg::Group*>(&node)) {
        for (std::size_t i = 0; i < group->childCount(); ++i) {
            markPhasesSet(*group->child(i));
        }
    }
}

// The vector splat examples (figures 5-8: VectorSplat and CombinedSplat with engine-driven
// phases, an SFNode mask shared by USE) pass through Coin as extension nodes: Coin reads each
// file, and what it writes back reads into the same graph.
TEST_F(CoinInteropTest, coinPassesTheVectorSplatExamplesThrough) {
    for (const char* example : {"figure5-tornado.iv", "figure6-jet-stream.iv",
                                "figure7-aerogel.iv", "figure8-clouds-winds.iv"}) {
        const sg::Node::Ptr scene =
            sg::SceneReader::readFile(std::string(TEXSPLAT_SOURCE_DIR "/examples/") + example);
        // Coin stores rotations as quaternions: a camera's orientation comes back a float step
        // off. The cameras are Coin's own nodes, checked by the tests above.
        auto& root = static_cast<sg::Group&>(*scene);
        for (std::size_t i = root.childCount(); i-- > 0;) {
            if (dynamic_cast<const Camera*>(root.child(i).get())) {
                root.removeChild(i);
            }
        }
        sg::WriteAction::writeFile(*scene, path("ours.iv"));
        EXPECT_NE(runCoin("describe " + path("ours.iv")).find("phase = ElapsedTime . timeOut"),
                  std::string::npos)
            << example;
        runCoin("rewrite " + path("ours.iv") + " " + path("coin.iv"));
        const sg::Node::Ptr reread = sg::SceneReader::readFile(path("coin.iv"));
        markPhasesSet(*scene);
        EXPECT_EQ(sg::test::graphDifference(*scene, *reread), "")
            << example << "\n" << readText(path("ours.iv")) << "\n" << readText(path("coin.iv"));
    }
}

} // namespace
} // namespace texsplat::nodes
