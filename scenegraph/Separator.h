#pragma once

#include "scenegraph/Group.h"

namespace texsplat::sg {

/// @brief A Group that saves the traversal state before its children and restores it after,
/// so transforms, materials etc. set below it do not leak to its siblings.
///
/// File format: `Separator { children... }` (no fields).
class Separator : public Declare<Separator, Group> {
public:
    /// @brief Scene-file name.
    static constexpr const char* kTypeName = "Separator";

    /// @brief Pushes the state, traverses the children, pops the state (also on exceptions).
    void doAction(Action& action) override;

protected:
    Separator() = default;
};

} // namespace texsplat::sg
