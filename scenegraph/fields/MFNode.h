#pragma once

#include "scenegraph/fields/Field.h"

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

namespace texsplat::sg {

/// @brief A list of node references (shared; null entries allowed). Parents and cycle checks as
/// for SFNode.
class MFNode final : public Field {
public:
    ~MFNode() override;

    /// @copydoc Field::typeName
    std::string_view typeName() const override { return "MFNode"; }

    /// @brief All nodes.
    const std::vector<std::shared_ptr<Node>>& values() const { return mValues; }

    /// @brief Number of entries.
    std::size_t size() const { return mValues.size(); }

    /// @brief Entry `index` (< size()).
    const std::shared_ptr<Node>& operator[](std::size_t index) const { return mValues[index]; }

    /// @brief Replaces all entries and notifies. Throws DataError on a cycle (nothing changes).
    void setValue(std::vector<std::shared_ptr<Node>> nodes);

    /// @brief Sets entry `index`, growing with null entries if needed, and notifies.
    void set1Value(std::size_t index, std::shared_ptr<Node> node);

    /// @copydoc Field::readValue
    void readValue(FieldValueReader& reader) override;

    /// @copydoc Field::writeValue
    void writeValue(FieldValueWriter& writer) const override;

    /// @copydoc Field::copyValueFrom
    void copyValueFrom(const Field& other) override;

protected:
    /// @brief Makes the container a parent of nodes set before registration.
    void attached() override;

private:
    void check(const std::vector<std::shared_ptr<Node>>& nodes) const;
    void link(const std::vector<std::shared_ptr<Node>>& nodes);
    void unlink(const std::vector<std::shared_ptr<Node>>& nodes);

    std::vector<std::shared_ptr<Node>> mValues;
};

} // namespace texsplat::sg
