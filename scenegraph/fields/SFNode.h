#pragma once

#include "scenegraph/fields/Field.h"

#include <memory>
#include <string_view>

namespace texsplat::sg {

/// @brief A reference to a node (shared, so DEF/USE works), or none.
///
/// When the field belongs to a node or engine, that container becomes a parent of the referenced
/// node for notification: a change in the referenced node notifies the container (e.g. a splat
/// node hears that its VolumeData changed). Setting a node that would make the graph contain
/// itself throws DataError.
class SFNode final : public Field {
public:
    ~SFNode() override;

    /// @copydoc Field::typeName
    std::string_view typeName() const override { return "SFNode"; }

    /// @brief The node, or nullptr.
    const std::shared_ptr<Node>& value() const { return mValue; }

    /// @brief Sets the node (nullptr for none) and notifies.
    void setValue(std::shared_ptr<Node> node);

    /// @brief Same as setValue().
    SFNode& operator=(std::shared_ptr<Node> node) {
        setValue(std::move(node));
        return *this;
    }

    /// @copydoc Field::readValue
    void readValue(FieldValueReader& reader) override;

    /// @copydoc Field::writeValue
    void writeValue(FieldValueWriter& writer) const override;

    /// @copydoc Field::copyValueFrom
    void copyValueFrom(const Field& other) override;

protected:
    /// @brief Makes the container a parent of a node set before registration.
    void attached() override;

private:
    std::shared_ptr<Node> mValue;
};

} // namespace texsplat::sg
