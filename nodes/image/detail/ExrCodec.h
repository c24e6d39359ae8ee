#pragma once

#include "nodes/image/Image.h"

#include <fstream>
#include <string>

namespace texsplat::image::detail {

/// @brief Writes `image` as OpenEXR: float32 channels R, G, B, A (premultiplied, as OpenEXR
/// itself defines them) and, when the image has depth, a float32 channel Z; ZIP compression
/// (lossless). `path` names the file in messages and in the stream.
void writeExr(const Image& image, std::ofstream& stream, const std::string& path);

/// @brief Reads an OpenEXR file's R, G, B (required), A (1 when absent) and Z (depth, when
/// present) channels as float32, whatever their stored type. The data window becomes the image.
/// Throws IoError("path: what") for unreadable files and DataError for missing channels.
Image readExr(const std::string& path);

} // namespace texsplat::image::detail
