#pragma once

#include "scenegraph/Fwd.h"

#include <cstdint>
#include <memory>
#include <string>

namespace texsplat::sg {

/// @brief What a field needs from the scene-file reader to parse its value.
///
/// The reader (scenegraph/io) implements this on its tokenizer; `Field::readValue()` calls it.
/// Every read skips whitespace and comments first. On malformed input an implementation throws
/// ParseError located at the current token (`file:line:col: ...`); `fail()` lets a field report
/// its own errors (an unknown enum name) at that location.
class FieldValueReader {
public:
    virtual ~FieldValueReader() = default;

    /// @brief Reads a number as float (integers and `1e-3` forms; out-of-range is an error).
    virtual float readFloat() = 0;

    /// @brief Reads a decimal (or `0x` hexadecimal) 32-bit signed integer.
    virtual std::int32_t readInt32() = 0;

    /// @brief Reads a string: `"quoted"` (with `\"` and `\\` escapes) or one bare word.
    virtual std::string readString() = 0;

    /// @brief Reads one unquoted token: a name such as TRUE, MODULATE, or a number's text.
    virtual std::string readName() = 0;

    /// @brief If the next character is `c` (`[`, `]` or `,`), consumes it and returns true.
    virtual bool readChar(char c) = 0;

    /// @brief Reads a node value: a node body, `DEF name Node {...}`, `USE name`, or `NULL`
    /// (returns nullptr).
    virtual std::shared_ptr<Node> readNode() = 0;

    /// @brief Throws ParseError at the current location with `message`.
    [[noreturn]] virtual void fail(const std::string& message) = 0;

protected:
    FieldValueReader() = default;
    FieldValueReader(const FieldValueReader&) = default;
    FieldValueReader& operator=(const FieldValueReader&) = default;
};

} // namespace texsplat::sg
