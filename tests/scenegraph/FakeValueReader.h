#pragma once

// Test double of the scene reader's tokenizer: whitespace-separated tokens, `[ ] ,` as tokens of
// their own, "quoted strings" with \" and \\ escapes, and `NULL` / `USE name` node values.

#include "scenegraph/Error.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/FieldValueReader.h"

#include <cctype>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <string>

namespace texsplat::sg::test {

class FakeValueReader final : public FieldValueReader {
public:
    explicit FakeValueReader(std::string text, std::map<std::string, Node::Ptr> named = {})
        : mText(std::move(text)), mNamed(std::move(named)) {}

    float readFloat() override {
        // strtof, not stof: denormals are valid values, not range errors.
        return std::strtof(next().c_str(), nullptr);
    }
    std::int32_t readInt32() override { return std::stoi(next()); }
    std::string readString() override {
        skipSpace();
        if (mPos >= mText.size() || mText[mPos] != '"') {
            return next();
        }
        std::string value;
        for (++mPos; mPos < mText.size() && mText[mPos] != '"'; ++mPos) {
            if (mText[mPos] == '\\') {
                ++mPos;
            }
            value += mText[mPos];
        }
        ++mPos;
        return value;
    }
    std::string readName() override { return next(); }
    bool readChar(char c) override {
        skipSpace();
        if (mPos < mText.size() && mText[mPos] == c) {
            ++mPos;
            return true;
        }
        return false;
    }
    Node::Ptr readNode() override {
        const std::string token = next();
        if (token == "NULL") {
            return nullptr;
        }
        if (token != "USE") {
            fail("expected NULL or USE, got '" + token + "'");
        }
        return mNamed.at(next());
    }
    [[noreturn]] void fail(const std::string& message) override {
        throw ParseError("fake.iv:1:" + std::to_string(mPos + 1) + ": " + message);
    }
    bool isAtEnd() {
        skipSpace();
        return mPos == mText.size();
    }

private:
    void skipSpace() {
        while (mPos < mText.size() && std::isspace(static_cast<unsigned char>(mText[mPos]))) {
            ++mPos;
        }
    }
    std::string next() {
        skipSpace();
        if (mPos >= mText.size()) {
            fail("unexpected end of input");
        }
        const std::size_t start = mPos;
        while (mPos < mText.size() && !std::isspace(static_cast<unsigned char>(mText[mPos])) &&
               mText[mPos] != ',' && mText[mPos] != ']' && mText[mPos] != '[') {
            ++mPos;
        }
        return mText.substr(start, mPos - start);
    }

    std::string mText;
    std::map<std::string, Node::Ptr> mNamed;
    std::size_t mPos = 0;
};

} // namespace texsplat::sg::test
