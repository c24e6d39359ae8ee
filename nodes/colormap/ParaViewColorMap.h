#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace texsplat::colormap {

/// @brief A colour map as ParaView exports it ("Choose Preset" → Export): a JSON list of objects
/// with `Name`, `ColorSpace` and `RGBPoints` = [x0, r0, g0, b0, x1, r1, g1, b1, …].
///
/// The first map of the list is used (a file ParaView exports holds the one map chosen). The
/// points' x are data values of whatever range the map was exported for; like ParaView applying
/// a preset, they are rescaled so the first point sits at t = 0 and the last at t = 1 of the
/// transfer function's range. Colours are interpolated linearly in RGB whatever `ColorSpace`
/// says: maps with many points (ParaView's exports of viridis, turbo, …) look the same, a map
/// of three "Diverging" or "Lab" points differs a little between them. Opacity points
/// (`Points`) and `NanColor` are not read: opacity is the transfer function's extinction.
struct ParaViewColorMap {
    std::string name;              ///< `Name`, may be empty
    std::string colorSpace;        ///< `ColorSpace`, may be empty
    std::vector<float> positions;  ///< the x of RGBPoints rescaled to t in [0, 1], not decreasing
    std::vector<glm::vec3> colors; ///< the r, g, b of RGBPoints, one per position
};

/// @brief Reads the first colour map of a ParaView colour-map JSON file.
/// @throws IoError when the file cannot be read; ParseError "path:line:column: …" for JSON that
/// does not parse or nests objects and arrays deeper than 256 levels (nodes::detail::
/// kMaxJsonNesting, checked before the text is parsed); DataError "path: …" naming the map and what is wrong for JSON that is not a
/// colour map (no RGBPoints, a count not a multiple of 4, x decreasing, a colour outside [0, 1]).
ParaViewColorMap readParaViewColorMap(const std::string& path);

/// @brief readParaViewColorMap() on text already in memory; `path` only names it in messages.
ParaViewColorMap parseParaViewColorMap(const std::string& text, const std::string& path);

} // namespace texsplat::colormap
