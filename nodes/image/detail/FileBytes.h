#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace texsplat::image::detail {

/// @brief The whole contents of a file. Throws IoError("path: cannot open: <reason>") when it
/// cannot be opened or read, and before opening it when it is not a regular file.
std::vector<char> readFileBytes(const std::string& path);

/// @brief What decoding costs a pixel: the file's samples and the float image.
constexpr std::size_t kDecodeBytesPerPixel = 24;

/// @brief Checks the size an image file's header declares before it is decoded: throws
/// DataError when it exceeds kMaxReadPixels (see readImage()), ResourceError when decoding it
/// (kDecodeBytesPerPixel) would exceed the memory limit (texsplat::memoryLimit()).
void checkDecodedSize(const std::string& path, long long width, long long height);

} // namespace texsplat::image::detail
