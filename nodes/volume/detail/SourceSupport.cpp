#include "nodes/volume/detail/SourceSupport.h"

#include "scenegraph/Error.h"
#include "scenegraph/Log.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace texsplat::volume::detail {

std::ifstream openForReading(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw IoError(path + ": cannot open file (it is a folder)");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int reason = errno;
        throw IoError(path + ": cannot open file (" +
                      (reason != 0 ? std::strerror(reason) : "unknown reason") + ")");
    }
    return in;
}

void checkFiniteVoxels(const std::string& source, const GridStatistics& statistics) {
    if (statistics.nonFiniteCount == 0)
        return;
    const bool one = statistics.nonFiniteCount == 1;
    const std::string count = std::to_string(statistics.nonFiniteCount);
    if (statistics.finiteCount == 0)
        throw DataError(source + ": " +
                        (one ? std::string("its only voxel is") : "all " + count + " voxels are") +
                        " NaN or infinite; nothing to draw");
    log(LogLevel::Warning, source + ": " + count + (one ? " voxel is" : " voxels are") +
                               " NaN or infinite; treated as empty");
}

} // namespace texsplat::volume::detail
