#pragma once

#include "scenegraph/EnumNames.h"
#include "scenegraph/Group.h"
#include "scenegraph/fields/SFEnum.h"

namespace texsplat::sg {

/// @brief Whether a Separator caches or culls (Inventor's SoSeparator::CacheEnabled).
enum class CacheEnabled {
    Off,  ///< never
    On,   ///< always
    Auto, ///< when the implementation thinks it pays
};

/// @brief Scene-file names of CacheEnabled.
inline const EnumNames kCacheEnabledNames{
    {"OFF", CacheEnabled::Off}, {"ON", CacheEnabled::On}, {"AUTO", CacheEnabled::Auto}};

/// @brief A Group that saves the traversal state before its children and restores it after,
/// so transforms, materials etc. set below it do not leak to its siblings.
///
/// Its fields are Inventor's caching and culling hints. They are read and written, so files
/// pass through texsplat and Coin unchanged, but not used by texsplat: it keeps no render
/// caches and culls nothing per Separator.
///
/// File format:
/// @code
/// Separator {
///     renderCaching       AUTO   # SFEnum: OFF, ON, AUTO
///     boundingBoxCaching  AUTO   # SFEnum: OFF, ON, AUTO
///     renderCulling       AUTO   # SFEnum: OFF, ON, AUTO
///     pickCulling         AUTO   # SFEnum: OFF, ON, AUTO
///     children...
/// }
/// @endcode
class Separator : public Declare<Separator, Group> {
public:
    /// @brief Scene-file name.
    static constexpr const char* kTypeName = "Separator";

    /// @brief Inventor's render-cache hint (CacheEnabled); read and written, not used.
    SFEnum renderCaching;
    /// @brief Inventor's bounding-box-cache hint (CacheEnabled); read and written, not used.
    SFEnum boundingBoxCaching;
    /// @brief Inventor's view-frustum culling hint (CacheEnabled); read and written, not used.
    SFEnum renderCulling;
    /// @brief Inventor's pick culling hint (CacheEnabled); read and written, not used.
    SFEnum pickCulling;

    /// @brief Pushes the state, traverses the children, pops the state (also on exceptions).
    void doAction(Action& action) override;

protected:
    Separator();
};

} // namespace texsplat::sg
