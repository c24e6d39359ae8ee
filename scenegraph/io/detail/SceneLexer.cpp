#include "scenegraph/io/detail/SceneLexer.h"

#include "scenegraph/Error.h"

#include <cstdio>

namespace texsplat::sg::detail {

namespace {

constexpr std::string_view kHeader = "#Inventor V2.1 ascii";
// Longest excerpt of a bad token quoted in a message.
constexpr std::size_t kMaxQuoted = 40;

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

bool isControl(char c) {
    const auto byte = static_cast<unsigned char>(c);
    return (byte < 0x20 && !isSpace(c)) || byte == 0x7f;
}

bool isWordChar(char c) {
    return !isSpace(c) && !isControl(c) && std::string_view("{}[],\"'#\\").find(c) == std::string_view::npos;
}

// Inventor's base-name characters (Coin's SbName::isBaseNameChar) except that '+' is kept:
// Coin writes shared unnamed nodes as `DEF +0`, and `name+1` for repeated names. List
// punctuation also ends a name, so `[ USE a, USE b ]` reads as two references.
bool isNameChar(char c) {
    return !isSpace(c) && !isControl(c) && std::string_view("\"'.\\{}[],").find(c) == std::string_view::npos;
}

} // namespace

std::string SceneLexer::quote(std::string_view text) {
    std::string quoted;
    for (std::size_t i = 0; i < text.size() && i < kMaxQuoted; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x20 || byte >= 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned>(byte));
            quoted += escaped;
        } else {
            quoted += text[i];
        }
    }
    if (text.size() > kMaxQuoted) {
        quoted += "...";
    }
    return "'" + quoted + "'";
}

SceneLexer::SceneLexer(std::string_view text, std::string fileName)
    : mText(text), mFileName(std::move(fileName)) {}

void SceneLexer::readHeader() {
    std::string_view line = mText.substr(0, mText.find('\n'));
    while (!line.empty() && isSpace(line.back())) {
        line.remove_suffix(1);
    }
    if (mText.empty()) {
        fail({}, "empty file, expected '" + std::string(kHeader) + "'");
    }
    if (line.substr(0, 11) == "#Inventor V" && line.size() > 11 &&
        line.substr(line.size() - 7) == " binary") {
        fail({}, "binary Inventor files are not supported, expected '" + std::string(kHeader) +
                     "'");
    }
    if (line != kHeader && line != "#Inventor V2.0 ascii") {
        fail({}, "not an Inventor file: expected '" + std::string(kHeader) +
                     "' on the first line, got " + quote(line));
    }
    while (mPosition < line.size()) {
        advance();
    }
}

bool SceneLexer::isAtEnd() {
    skipSpace();
    return mPosition == mText.size();
}

char SceneLexer::peek() {
    skipSpace();
    if (mPosition == mText.size()) {
        return '\0';
    }
    const char c = mText[mPosition];
    if (isControl(c)) {
        fail(mLocation, "unexpected control character " + quote(mText.substr(mPosition, 1)) +
                            (c == '\0' ? " (binary data?)" : ""));
    }
    return c;
}

bool SceneLexer::consumeIf(char c) {
    if (peek() != c || c == '\0') {
        return false;
    }
    advance();
    return true;
}

bool SceneLexer::consumeKeywordBeforeList(std::string_view keyword) {
    peek();
    const std::size_t position = mPosition;
    const SourceLocation location = mLocation;
    if (readWhile(isNameChar) == keyword && peek() == '[') {
        return true;
    }
    mPosition = position;
    mLocation = location;
    return false;
}

std::string SceneLexer::readWord() {
    peek();
    return readWhile(isWordChar);
}

std::string SceneLexer::peekWord() {
    peek();
    std::size_t end = mPosition;
    while (end < mText.size() && isWordChar(mText[end])) {
        ++end;
    }
    return std::string(mText.substr(mPosition, end - mPosition));
}

std::string SceneLexer::readName() {
    peek();
    return readWhile(isNameChar);
}

std::string SceneLexer::readQuoted() {
    const SourceLocation start = location();
    std::string text;
    advance();
    while (mPosition < mText.size() && mText[mPosition] != '"') {
        if (mText[mPosition] == '\\' && mPosition + 1 < mText.size() &&
            (mText[mPosition + 1] == '"' || mText[mPosition + 1] == '\\')) {
            advance();
        }
        text += mText[mPosition];
        advance();
    }
    if (mPosition == mText.size()) {
        fail(mLocation, "expected '\"' to close the string opened at " + format(start) +
                            ", got end of file");
    }
    advance();
    return text;
}

SourceLocation SceneLexer::location() {
    skipSpace();
    return mLocation;
}

std::string SceneLexer::describeNext() {
    const char c = peek();
    if (c == '\0') {
        return "end of file";
    }
    std::size_t end = mPosition + 1;
    if (c == '"') {
        // The whole string, if it closes on this line.
        while (end < mText.size() && mText[end] != '"' && mText[end] != '\n') {
            end += mText[end] == '\\' && end + 1 < mText.size() ? 2 : 1;
        }
        end += end < mText.size() && mText[end] == '"' ? 1 : 0;
    } else if (isWordChar(c)) {
        end = mPosition + peekWord().size();
    }
    return quote(mText.substr(mPosition, end - mPosition));
}

void SceneLexer::fail(SourceLocation where, const std::string& message) const {
    throw ParseError(mFileName + ":" + format(where) + ": " + message);
}

std::string SceneLexer::format(SourceLocation where) {
    return std::to_string(where.line) + ":" + std::to_string(where.column);
}

void SceneLexer::skipSpace() {
    while (mPosition < mText.size()) {
        const char c = mText[mPosition];
        if (c == '#') {
            while (mPosition < mText.size() && mText[mPosition] != '\n') {
                advance();
            }
        } else if (isSpace(c)) {
            advance();
        } else {
            return;
        }
    }
}

void SceneLexer::advance() {
    if (mText[mPosition] == '\n') {
        ++mLocation.line;
        mLocation.column = 1;
    } else {
        ++mLocation.column;
    }
    ++mPosition;
}

std::string SceneLexer::readWhile(bool (*accept)(char)) {
    const std::size_t start = mPosition;
    while (mPosition < mText.size() && accept(mText[mPosition])) {
        advance();
    }
    return std::string(mText.substr(start, mPosition - start));
}

} // namespace texsplat::sg::detail
