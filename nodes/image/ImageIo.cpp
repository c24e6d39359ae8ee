#include "nodes/image/ImageIo.h"

#include "nodes/image/detail/PngCodec.h"
#include "scenegraph/AtomicFile.h"
#include "scenegraph/Error.h"
#include "scenegraph/FileExtension.h"

#include <sstream>

#ifdef TEXSPLAT_WITH_EXR
#include "nodes/image/detail/ExrCodec.h"
#endif

namespace texsplat::image {

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

ImageFormat supportedImageFormatOf(const std::string& path) {
    const ImageFormat format = imageFormatOf(path);
    if (format == ImageFormat::Exr && !isExrSupported())
        throw IoError(path + ": OpenEXR support is not built in (configure with "
                             "-DTEXSPLAT_WITH_EXR=ON)");
    return format;
}

void writeImage(const Image& image, const std::string& path) {
    const ImageFormat format = supportedImageFormatOf(path);
    writeFileAtomically(path, [&](std::ofstream& stream) {
        if (format == ImageFormat::Png)
            detail::writePng(image, stream, path);
#ifdef TEXSPLAT_WITH_EXR
        else
            detail::writeExr(image, stream, path);
#endif
    });
}

std::string pngBytes(const Image& image) {
    std::ostringstream stream;
    detail::writePng(image, stream, "<memory>");
    return stream.str();
}

Image readImage(const std::string& path) {
    [[maybe_unused]] const ImageFormat format = supportedImageFormatOf(path);
#ifdef TEXSPLAT_WITH_EXR
    if (format == ImageFormat::Exr)
        return detail::readExr(path);
#endif
    return detail::readPng(path);
}

} // namespace texsplat::image
