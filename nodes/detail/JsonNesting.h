#pragma once

#include <string>
#include <string_view>

namespace texsplat::nodes::detail {

/// @brief The deepest nesting of JSON objects and arrays texsplat parses. Copying or converting
/// a parsed document recurses once per level (tinygltf's values, nlohmann::json's copy): 20 000
/// levels overflow an 8 MB stack, 100 000 a 4 MB one. Real files nest a handful of levels.
constexpr int kMaxJsonNesting = 256;

/// @brief Refuses JSON nested deeper than kMaxJsonNesting before a parser sees it, with
/// ParseError "<where>:<line>:<column>: JSON objects and arrays nested deeper than the limit of
/// 256 levels"; `where` names the text ("model.gltf", "model.glb (JSON chunk)", "map.json").
/// Brackets inside strings do not count; the scan is not a validator, the parser reports what
/// else is wrong.
void checkJsonNesting(std::string_view json, const std::string& where);

} // namespace texsplat::nodes::detail
