#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace texsplat::sg::detail {

/// @brief A line and column in a scene file (both from 1; columns count bytes).
struct SourceLocation {
    int line = 1;
    int column = 1;
};

/// @brief The characters of an Inventor ASCII file: whitespace and `#` comments, words,
/// names, quoted strings and single punctuation characters, each with its location.
///
/// The lexer does not know the grammar; SceneParser asks it for what it expects next. Every
/// failure throws ParseError("file:line:col: message"). Control characters (NUL included)
/// outside strings are rejected where they appear, so binary data never gets far.
class SceneLexer {
public:
    /// @brief Lexes `text`; `fileName` starts every message.
    SceneLexer(std::string_view text, std::string fileName);

    /// @brief Checks the `#Inventor V2.x ascii` header line and moves past it.
    void readHeader();

    /// @brief Skips whitespace and comments; true when nothing is left.
    bool isAtEnd();

    /// @brief Skips whitespace and comments and returns the next character ('\0' at the end).
    char peek();

    /// @brief Skips whitespace and comments; consumes `c` and returns true if it comes next.
    bool consumeIf(char c);

    /// @brief Consumes the name `keyword` if it comes next and is followed by `[` (a field
    /// description: `fields [`); otherwise consumes nothing and returns false.
    bool consumeKeywordBeforeList(std::string_view keyword);

    /// @brief A value word: everything up to whitespace or one of `{}[],"'#\`. Empty when the
    /// next character cannot start one.
    std::string readWord();

    /// @brief The word readWord() would return, without consuming it.
    std::string peekWord();

    /// @brief An Inventor name (DEF/USE names, type and field names): everything up to
    /// whitespace, a control character or one of `"'.\{}[],`. Empty when none comes next.
    std::string readName();

    /// @brief A double-quoted string (the next character must be `"`), with `\"` and `\\`.
    std::string readQuoted();

    /// @brief Where the next token starts (after skipping whitespace and comments).
    SourceLocation location();

    /// @brief The next token as a message shows it: `'word'`, `'"a string"'`, `'}'` or
    /// `end of file`.
    std::string describeNext();

    /// @brief Throws ParseError located at `where`.
    [[noreturn]] void fail(SourceLocation where, const std::string& message) const;

    /// @brief Formats `where` as `line:col`, for messages that point back (`opened at 3:1`).
    static std::string format(SourceLocation where);

    /// @brief `text` as every message quotes what the file holds: in single quotes, bytes outside
    /// printable ASCII as `\xNN`, cut after 40 bytes with `...`.
    static std::string quote(std::string_view text);

private:
    void skipSpace();
    void advance();
    std::string readWhile(bool (*accept)(char));

    std::string_view mText;
    std::string mFileName;
    std::size_t mPosition = 0;
    SourceLocation mLocation;
};

} // namespace texsplat::sg::detail
