#pragma once

#include "nodes/image/Image.h"

#include <ostream>
#include <string>

namespace texsplat::image::detail {

/// @brief Encodes `image` as an 8-bit RGBA PNG with straight (not premultiplied) alpha, the
/// form PNG viewers expect, and the colour values as they are: display (sRGB) values, as colour
/// maps give them (see docs/images.md). `path` only names the file in messages.
void writePng(const Image& image, std::ostream& stream, const std::string& path);

/// @brief Reads an 8- or 16-bit PNG (gray, gray+alpha, RGB or RGBA) into premultiplied floats
/// (each value over its largest, then times alpha), undoing writePng(). Throws
/// IoError("path: what").
Image readPng(const std::string& path);

} // namespace texsplat::image::detail
