#pragma once

#include "scenegraph/Fwd.h"

#include <memory>
#include <string_view>

namespace texsplat::sg {

/// @brief What a field needs from the scene-file writer to print its value.
///
/// `Field::writeValue()` formats every value itself (ValueFormat.h: shortest round-trip floats,
/// quoted strings) and hands the tokens here; the writer decides spacing, line breaks and
/// indentation. A multi-valued field with exactly one value writes it without brackets;
/// otherwise it calls `beginList()`, `writeToken()` once per value, `endList()`.
class FieldValueWriter {
public:
    virtual ~FieldValueWriter() = default;

    /// @brief One complete value, already formatted (`1.6`, `TRUE`, `"a b"`, `0 0 1 1.5708`).
    virtual void writeToken(std::string_view text) = 0;

    /// @brief A node value: the writer prints `NULL`, `USE name` or the whole node.
    virtual void writeNode(const std::shared_ptr<Node>& node) = 0;

    /// @brief Opens a multi-value list (`[`).
    virtual void beginList() = 0;

    /// @brief Closes a multi-value list (`]`).
    virtual void endList() = 0;

protected:
    FieldValueWriter() = default;
    FieldValueWriter(const FieldValueWriter&) = default;
    FieldValueWriter& operator=(const FieldValueWriter&) = default;
};

} // namespace texsplat::sg
