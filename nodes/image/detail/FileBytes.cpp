#include "nodes/image/detail/FileBytes.h"

#include "scenegraph/Error.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace texsplat::image::detail {

std::vector<char> readFileBytes(const std::string& path) {
    std::ifstream stream(path, std::ios::binary);
    if (!stream)
        throw IoError(path + ": cannot open: " + std::strerror(errno));
    std::vector<char> bytes((std::istreambuf_iterator<char>(stream)),
                            std::istreambuf_iterator<char>());
    if (stream.bad())
        throw IoError(path + ": cannot read: " + std::strerror(errno));
    return bytes;
}

} // namespace texsplat::image::detail
