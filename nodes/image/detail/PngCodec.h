#pragma once

#include "nodes/image/Image.h"

#include <ostream>
#include <string>

namespace texsplat::image::detail {

/// @brief Encodes `image` as an 8-bit RGBA PNG with straight (not premultiplied) alpha and
/// sRGB-encoded color, the form PNG viewers expect (see docs/images.md). `path` only names the
/// file in messages.
void writePng(const Image& image, std::ostream& stream, const std::string& path);

/// @brief Reads an 8- or 16-bit PNG (gray, gray+alpha, RGB or RGBA) into linear premultiplied
/// floats, undoing writePng()'s encoding. Throws IoError("path: what").
Image readPng(const std::string& path);

} // namespace texsplat::image::detail
