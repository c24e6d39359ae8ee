#pragma once

// The texsplat side of the Coin3D interop tests (tests/scenegraph and tests/nodes): a fixture
// that runs coin_interop_tool (CoinInteropTool.cpp, linked against Coin), our own description
// of a graph and of a type's fields in the tool's format, and a comparison of two such
// descriptions that reads numbers as numbers.

#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/FieldContainer.h"
#include "scenegraph/Group.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace texsplat::sg::test {

/// Runs coin_interop_tool in a temporary folder of its own per test; skips the test when the
/// build found no Coin (TEXSPLAT_COIN_INTEROP_TOOL undefined; TEXSPLAT_REQUIRE_COIN makes that a
/// configuration error instead).
class CoinInteropFixture : public ::testing::Test {
protected:
    void SetUp() override {
#ifndef TEXSPLAT_COIN_INTEROP_TOOL
        GTEST_SKIP() << "Coin3D (libcoin-dev, CMake package Coin) was not found when "
                        "configuring: the Coin interop tests are skipped";
#endif
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDirectory = std::filesystem::path(::testing::TempDir()) /
                     ("texsplat_coin_" + std::to_string(getpid()) + "_" + info->name());
        std::filesystem::create_directories(mDirectory);
    }
    void TearDown() override {
        if (!mDirectory.empty()) {
            std::filesystem::remove_all(mDirectory);
        }
    }

    std::string path(const std::string& name) const { return (mDirectory / name).string(); }

    // Runs coin_interop_tool with `arguments`; returns its stdout, fails the test on exit != 0.
    std::string runCoin([[maybe_unused]] const std::string& arguments) const {
#ifdef TEXSPLAT_COIN_INTEROP_TOOL
        const std::string output = path("coin_stdout.txt");
        const std::string command = std::string(TEXSPLAT_COIN_INTEROP_TOOL) + " " + arguments +
                                    " >" + output + " 2>" + path("coin_stderr.txt");
        const int status = std::system(command.c_str());
        EXPECT_EQ(status, 0) << "coin_interop_tool " << arguments << ": "
                             << readText(path("coin_stderr.txt"));
        return readText(output);
#else
        return {}; // not reached: SetUp() skips every test in a build without Coin
#endif
    }

    static std::string readText(const std::string& file) {
        std::ifstream stream(file);
        std::ostringstream text;
        text << stream.rdbuf();
        return text.str();
    }

private:
    std::filesystem::path mDirectory;
};

namespace detail {

inline void describeFields(const FieldContainer& container, int depth, std::string& out);

inline void describeNode(const Node& node, int depth, std::string& out) {
    out += std::string(static_cast<std::size_t>(depth) * 2, ' ') + node.typeName();
    if (!node.name().empty()) {
        out += " \"" + node.name() + "\"";
    }
    out += "\n";
    describeFields(node, depth + 1, out);
    if (const auto* group = dynamic_cast<const Group*>(&node)) {
        for (const Node::Ptr& child : group->children()) {
            describeNode(*child, depth + 1, out);
        }
    }
}

inline void describeFields(const FieldContainer& container, int depth, std::string& out) {
    const std::string indent(static_cast<std::size_t>(depth) * 2, ' ');
    for (const Field* field : container.fields()) {
        if (field->typeName() == "SFTrigger") {
            continue; // no value to describe, as on the Coin side
        }
        const Field* source = field->connectedField();
        if (const EngineOutputBase* output = field->connectedOutput()) {
            out += indent + field->name() + " = " + output->engine().typeName() + " . " +
                   output->name() + "\n";
            describeFields(output->engine(), depth + 2, out);
        } else if (source != nullptr && source->container() != nullptr) {
            out += indent + field->name() + " = " + source->container()->typeName() + " . " +
                   source->name() + "\n";
        } else if (!field->isDefault()) {
            out += indent + field->name() + " " + field->valueText() + "\n";
        }
    }
}

// Tokens of a description line, brackets and commas dropped.
inline std::vector<std::string> tokens(const std::string& line) {
    std::string spaced = line;
    std::replace_if(
        spaced.begin(), spaced.end(), [](char c) { return c == '[' || c == ']' || c == ','; },
        ' ');
    std::istringstream stream(spaced);
    std::vector<std::string> words;
    for (std::string word; stream >> word;) {
        words.push_back(word);
    }
    return words;
}

// Coin prints floats with 8 digits and turns rotations into quaternions and back: numbers are
// the same when they agree to float precision.
inline bool sameToken(const std::string& a, const std::string& b) {
    char* endA = nullptr;
    char* endB = nullptr;
    const float x = std::strtof(a.c_str(), &endA);
    const float y = std::strtof(b.c_str(), &endB);
    if (*endA != '\0' || *endB != '\0' || endA == a.c_str() || endB == b.c_str()) {
        return a == b;
    }
    return std::abs(x - y) <= 1e-5f * std::max(1.0f, std::abs(x));
}

} // namespace detail

/// The graph under `root` in coin_interop_tool's `describe` format: a line per node (type and
/// name), then its fields that are not default (`name value`), a connection as
/// `name = Type . source` followed by an engine's fields, then the children.
inline std::string describeScene(const Node& root) {
    std::string out;
    detail::describeNode(root, 0, out);
    return out;
}

/// `container`'s fields in coin_interop_tool's `fields` format: `TYPE NAME DEFAULT` per field,
/// then `output TYPE NAME` per engine output.
inline std::string describeFieldDeclarations(const FieldContainer& container) {
    std::string out = container.typeName() + "\n";
    for (const Field* field : container.fields()) {
        out += "  " + std::string(field->typeName()) + " " + field->name() + " " +
               field->valueText() + "\n";
    }
    if (const auto* engine = dynamic_cast<const Engine*>(&container)) {
        for (const EngineOutputBase* output : engine->outputs()) {
            out += "  output " + std::string(output->typeName()) + " " + output->name() + "\n";
        }
    }
    return out;
}

/// "" when two descriptions have the same lines, word by word with numbers compared as floats
/// (brackets and commas ignored); otherwise the first lines that differ.
inline std::string descriptionDifference(const std::string& coin, const std::string& ours) {
    std::istringstream coinLines(coin);
    std::istringstream ourLines(ours);
    std::string coinLine;
    std::string ourLine;
    for (int number = 1;; ++number) {
        const bool hasCoin = static_cast<bool>(std::getline(coinLines, coinLine));
        const bool hasOurs = static_cast<bool>(std::getline(ourLines, ourLine));
        if (!hasCoin && !hasOurs) {
            return "";
        }
        const std::vector<std::string> a =
            hasCoin ? detail::tokens(coinLine) : std::vector<std::string>{};
        const std::vector<std::string> b =
            hasOurs ? detail::tokens(ourLine) : std::vector<std::string>{};
        const bool same = hasCoin == hasOurs && a.size() == b.size() &&
                          std::equal(a.begin(), a.end(), b.begin(), detail::sameToken) &&
                          coinLine.find_first_not_of(' ') == ourLine.find_first_not_of(' ');
        if (!same) {
            return "line " + std::to_string(number) + ": Coin '" +
                   (hasCoin ? coinLine : "(end)") + "', texsplat '" +
                   (hasOurs ? ourLine : "(end)") + "'";
        }
    }
}

} // namespace texsplat::sg::test
