#pragma once

#include "scenegraph/Fwd.h"

#include <map>
#include <string>

namespace texsplat::sg::detail {

/// @brief The field descriptions of `type`, collected from one instance made for it: the text
/// its constructors gave addField() and addOutput(), by field (or output) name. Empty for an
/// abstract type. Instances made at other times keep no description, so nodes carry none.
std::map<std::string, std::string, std::less<>> collectFieldDescriptions(const NodeType& type);

/// @brief Called by addField() and addOutput(): keeps `description` of `container`'s field
/// `name` while collectFieldDescriptions() makes an instance on this thread, else does nothing.
void recordFieldDescription(const FieldContainer& container, const std::string& name,
                            const char* description);

} // namespace texsplat::sg::detail
