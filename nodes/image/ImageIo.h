#pragma once

#include "nodes/image/Image.h"

#include <cstddef>
#include <string>

namespace texsplat::image {

/// @brief The image file formats texsplat reads and writes, chosen by file extension.
enum class ImageFormat {
    Png, ///< `.png`: 8-bit RGBA, straight alpha, colour as it is (display values), for people
    Exr, ///< `.exr`: OpenEXR float32 RGBA (premultiplied) + optional Z, for numbers
};

/// @brief The format of `path` from its extension, case-insensitively (`.png`, `.exr`).
///
/// Throws IoError("out.tif: unknown image extension '.tif' (supported: .png, .exr)").
ImageFormat imageFormatOf(const std::string& path);

/// @brief Whether this build can read and write OpenEXR (the TEXSPLAT_WITH_EXR option).
bool isExrSupported();

/// @brief imageFormatOf(), and a format this build can read and write: lets a command refuse a
/// path before any work. Throws IoError("out.exr: OpenEXR support is not built in (configure
/// with -DTEXSPLAT_WITH_EXR=ON)") for `.exr` without OpenEXR.
ImageFormat supportedImageFormatOf(const std::string& path);

/// @brief Writes `image` to `path` in the format its extension names.
///
/// The file appears all at once: the image is written to a temporary file in the same
/// directory and renamed over `path`, so a failed write leaves no partial output and no
/// temporary file, and an existing file is replaced only by a complete one. Every failure
/// throws IoError("path: what") (unknown extension, unwritable or missing directory, full
/// disk, a build without OpenEXR).
void writeImage(const Image& image, const std::string& path);

/// @brief The bytes of the PNG file writeImage() writes for `image` (8-bit RGBA, straight alpha,
/// the colour values as they are), for a program that shows it without a file (a notebook).
std::string pngBytes(const Image& image);

/// @brief The most pixels readImage() decodes: 8192 × 8192. Decoding takes about 24 bytes a
/// pixel (the file's samples and the float image), 1.5 GiB here, so `compare` of two such images
/// stays near 3 GiB; a file whose header declares more (a 1 MB PNG may declare 16000 × 16000)
/// is refused before anything is decoded.
constexpr std::size_t kMaxReadPixels = std::size_t{1} << 26;

/// @brief Reads the image at `path` (format from its extension): PNG is converted to
/// premultiplied floats (each value over its largest, times alpha), OpenEXR is read as float32.
/// Throws IoError("path: what") for a missing, unreadable or malformed file, or one that is not
/// a regular file (a FIFO, a device); DataError
/// for an EXR without R, G, B channels, and for an image of more than kMaxReadPixels pixels
/// ("big.png: the image is 16000 x 16000 pixels; texsplat reads images of at most 67108864
/// pixels (8192 x 8192)"); ResourceError, before decoding, when decoding would need more than
/// the memory limit (texsplat::memoryLimit(), `--memory-limit`).
Image readImage(const std::string& path);

} // namespace texsplat::image
