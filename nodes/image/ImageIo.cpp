#include "nodes/image/ImageIo.h"

#include "nodes/image/detail/PngCodec.h"
#include "scenegraph/AtomicFile.h"
#include "scenegraph/Error.h"

#ifdef TEXSPLAT_WITH_EXR
#include "nodes/image/detail/ExrCodec.h"
#endif

#include <algorithm>
#include <cctype>

namespace texsplat::image {
namespace {

constexpr const char* kSupportedExtensions = ".png, .exr";

std::string extensionOf(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string extension = path.substr(dot);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

/// The error for an .exr path in a build without OpenEXR; names the option that turns it on.
[[maybe_unused]] IoError exrNotBuilt(const std::string& path) {
    return IoError(path + ": OpenEXR support is not built in (configure with "
                          "-DTEXSPLAT_WITH_EXR=ON)");
}

} // namespace

ImageFormat imageFormatOf(const std::string& path) {
    const std::string extension = extensionOf(path);
    if (extension == ".png")
        return ImageFormat::Png;
    if (extension == ".exr")
        return ImageFormat::Exr;
    const std::string found =
        extension.empty() ? "no image extension" : "unknown image extension '" + extension + "'";
    throw IoError(path + ": " + found + " (supported: " + kSupportedExtensions + ")");
}

bool isExrSupported() {
#ifdef TEXSPLAT_WITH_EXR
    return true;
#else
    return false;
#endif
}

void writeImage(const Image& image, const std::string& path) {
    const ImageFormat format = imageFormatOf(path);
#ifndef TEXSPLAT_WITH_EXR
    if (format == ImageFormat::Exr)
        throw exrNotBuilt(path);
#endif
    writeFileAtomically(path, [&](std::ofstream& stream) {
        if (format == ImageFormat::Png)
            detail::writePng(image, stream, path);
#ifdef TEXSPLAT_WITH_EXR
        else
            detail::writeExr(image, stream, path);
#endif
    });
}

Image readImage(const std::string& path) {
    if (imageFormatOf(path) == ImageFormat::Png)
        return detail::readPng(path);
#ifdef TEXSPLAT_WITH_EXR
    return detail::readExr(path);
#else
    throw exrNotBuilt(path);
#endif
}

} // namespace texsplat::image
