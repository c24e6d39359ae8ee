#pragma once

#include <string>
#include <vector>

namespace texsplat::image {

/// @brief Writes `gray` (`width` × `height` floats, row 0 first: PFM stores rows bottom to top)
/// as a little-endian grayscale PFM ("Pf"), all at once (scenegraph/AtomicFile.h). The bytes
/// come from the IEEE bit patterns, so the file is the same on any host.
/// @throws IoError when the file cannot be written.
void writeGrayPfm(const std::string& path, int width, int height, const std::vector<float>& gray);

} // namespace texsplat::image
