#include "nodes/volume/detail/SourceSupport.h"

#include "scenegraph/Error.h"
#include "scenegraph/InputFile.h"
#include "scenegraph/Log.h"
#include "scenegraph/MemoryLimit.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace texsplat::volume::detail {

std::ifstream openForReading(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw IoError(path + ": cannot open file (it is a folder)");
    requireRegularFile(path, "file");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int reason = errno;
        throw IoError(path + ": cannot open file (" +
                      (reason != 0 ? std::strerror(reason) : "unknown reason") + ")");
    }
    return in;
}

std::int64_t fileSize(const std::string& path) {
    std::error_code error;
    const std::uintmax_t bytes = std::filesystem::file_size(path, error);
    if (error)
        throw IoError(path + ": cannot read file size (" + error.message() + ")");
    return static_cast<std::int64_t>(bytes);
}

void checkFitsInMemory(const std::string& what, std::uint64_t bytes) {
    checkMemory(what, bytes, "use a volume of lower resolution, or a larger --memory-limit");
}

void checkGridFitsInMemory(const std::string& source, const GridGeometry& geometry,
                           int components) {
    const glm::i64vec3& dims = geometry.dims();
    checkFitsInMemory(source + ": a grid of " + std::to_string(dims.x) + " x " +
                          std::to_string(dims.y) + " x " + std::to_string(dims.z) + " voxels x " +
                          std::to_string(components) + (components == 1 ? " float" : " floats"),
                      byteProduct(static_cast<std::uint64_t>(geometry.voxelCount()),
                                  static_cast<std::uint64_t>(components) * sizeof(float)));
}

std::uint64_t maxDeflatedBytes(std::uint64_t compressedBytes) {
    return byteSum(byteProduct(compressedBytes, kMaxDeflateRatio), 258);
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
