#pragma once

#include "scenegraph/Group.h"
#include "scenegraph/fields/Fields.h"

#include <cstdint>

namespace texsplat::sg {

/// @brief A Group that traverses one child chosen by `whichChild`, none, or all.
///
/// `whichChild`: an index traverses that child; kNone (-1) traverses none, kAll (-3) all of
/// them in order; any other value (out of range, -2) traverses none. Traversal state is not
/// saved (a Switch is not a Separator). SearchAction with `setSearchingAll(true)` looks at all
/// children regardless.
///
/// File format:
/// @code
/// Switch {
///     whichChild -1   # SFInt32
///     children...
/// }
/// @endcode
class Switch : public Declare<Switch, Group> {
public:
    /// @brief Scene-file name.
    static constexpr const char* kTypeName = "Switch";

    /// @brief whichChild value that traverses no child.
    static constexpr std::int32_t kNone = -1;

    /// @brief whichChild value that traverses all children.
    static constexpr std::int32_t kAll = -3;

    /// @brief The chosen child, kNone or kAll. Default kNone.
    SFInt32 whichChild;

    /// @brief Traverses the chosen children.
    void doAction(Action& action) override;

    /// @brief Reports a match, then traverses all children when the action searches all,
    /// otherwise the chosen ones.
    void search(SearchAction& action) override;

protected:
    Switch();
};

} // namespace texsplat::sg
