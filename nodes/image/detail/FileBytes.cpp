#include "nodes/image/detail/FileBytes.h"

#include "nodes/image/ImageIo.h"
#include "scenegraph/Error.h"
#include "scenegraph/InputFile.h"
#include "scenegraph/MemoryLimit.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace texsplat::image::detail {

std::vector<char> readFileBytes(const std::string& path) {
    requireRegularFile(path, "image file");
    std::ifstream stream(path, std::ios::binary);
    if (!stream)
        throw IoError(path + ": cannot open: " + std::strerror(errno));
    std::vector<char> bytes((std::istreambuf_iterator<char>(stream)),
                            std::istreambuf_iterator<char>());
    if (stream.bad())
        throw IoError(path + ": cannot read: " + std::strerror(errno));
    return bytes;
}

void checkDecodedSize(const std::string& path, long long width, long long height) {
    // Both sides come from a file's header: divide rather than multiply, which could overflow.
    constexpr auto kLimit = static_cast<long long>(kMaxReadPixels);
    const std::string size = std::to_string(width) + " x " + std::to_string(height) + " pixels";
    if (width > kLimit || height > kLimit || (height != 0 && width > kLimit / height))
        throw DataError(path + ": the image is " + size + "; texsplat reads images of at most " +
                        std::to_string(kMaxReadPixels) + " pixels (8192 x 8192)");
    checkMemory(path + ": decoding its " + size,
                static_cast<std::uint64_t>(width * height) * kDecodeBytesPerPixel,
                "use smaller images, or a larger --memory-limit");
}

} // namespace texsplat::image::detail
