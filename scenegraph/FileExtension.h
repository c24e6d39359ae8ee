#pragma once

#include <string>
#include <vector>

namespace texsplat {

/// @brief The extension of the file name in `path`, lower-cased and with its dot (".svg" for
/// "out/Plot.SVG"); empty when the name has no dot ("out.d/plot").
std::string fileExtension(const std::string& path);

/// @brief Throws IoError("p.png: unknown plot extension '.png' (supported: .svg)") unless
/// fileExtension(path) is one of `supported` (lower case, with their dots); `kind` names the
/// file in the message ("no plot extension" when the name has none; "the plot file name is
/// empty (supported extensions: .svg)" for an empty name). Writers call it before any
/// work, so a file name they would fill with the wrong format fails at once and writes nothing.
void requireFileExtension(const std::string& path, const std::vector<std::string>& supported,
                          const std::string& kind);

} // namespace texsplat
