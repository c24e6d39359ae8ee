#include "nodes/image/ImageIo.h"

#include "nodes/image/detail/PngCodec.h"
#include "scenegraph/AtomicFile.h"
#include "scenegraph/Error.h"
#include "scenegraph/FileExtension.h"

#ifdef TEXSPLAT_WITH_EXR
#include "nodes/image/detail/ExrCodec.h"
#endif

namespace texsplat::image {
namespace {

/// The error for an .exr path in a build without OpenEXR; names the option that turns it on.
[[maybe_unused]] IoError exrNotBuilt(const std::string& path) {
    return IoError(path + ": OpenEXR support is not built in (configure with "
                          "-DTEXSPLAT_WITH_EXR=ON)");
}

} // namespace

ImageFormat imageFormatOf(const std::string& path) {
    requireFileExtension(path, {".png", ".exr"}, "image");
    return fileExtension(path) == ".png" ? ImageFormat::Png : ImageFormat::Exr;
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
