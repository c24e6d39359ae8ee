#include "nodes/volume/NrrdVolume.h"

#include "nodes/volume/NrrdHeader.h"
#include "nodes/volume/detail/GzipInputStream.h"
#include "nodes/volume/detail/RawData.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace texsplat::volume {
namespace {

// A detached header's data file is relative to the header's folder.
std::string dataFilePath(const std::string& headerPath, const std::string& dataFile) {
    const std::filesystem::path name(dataFile);
    if (name.is_absolute())
        return dataFile;
    // unu writes "./name"; messages name the file without it.
    return (std::filesystem::path(headerPath).parent_path() / name).lexically_normal().string();
}

detail::FileAxes fileAxes(const NrrdHeader& header) {
    return {header.gridAxis, header.reversed};
}

// Skips `count` lines of `in`; answers the bytes skipped.
std::int64_t skipLines(std::istream& in, const std::string& path, std::int64_t count) {
    std::int64_t bytes = 0;
    for (std::int64_t line = 0; line < count; ++line) {
        char c = 0;
        while (in.get(c) && c != '\n')
            ++bytes;
        if (!in)
            throw DataError(path + ": the data ends within the " + std::to_string(count) +
                            " lines that 'line skip' skips");
        ++bytes;
    }
    return bytes;
}

void useRaw(std::istream& in, const std::string& path, const NrrdHeader& header,
            std::int64_t position, const std::string& asks, const detail::RawDataDecoder& use) {
    const std::int64_t needed = header.layout.dataBytes();
    std::int64_t available = detail::fileSize(path) - position;
    const std::int64_t skip = header.byteSkip == -1 ? std::max<std::int64_t>(0, available - needed)
                                                    : header.byteSkip;
    available -= skip;
    // What the data follow, for messages.
    const std::string after = skip > 0                 ? "the " + std::to_string(skip) +
                                                             " bytes of 'byte skip'"
                              : header.lineSkip > 0    ? std::string("the lines of 'line skip'")
                              : header.dataFile.empty() ? std::string("the header")
                                                        : std::string("the start of the file");
    if (available < needed)
        throw DataError(path + ": truncated data: " + asks + ", but only " +
                        std::to_string(std::max<std::int64_t>(0, available)) + " bytes follow " +
                        after);
    if (available > needed)
        throw DataError(path + ": data size mismatch: " + asks + ", but " +
                        std::to_string(available) + " bytes follow " + after +
                        " (for data at the end of a longer file, say 'byte skip: -1')");
    in.seekg(static_cast<std::streamoff>(position + skip));
    use({in, path, header.layout, detail::RawOrder::XFastest, fileAxes(header)});
}

void useGzip(std::istream& in, const std::string& path, const NrrdHeader& header,
             std::int64_t position, const std::string& asks, const detail::RawDataDecoder& use) {
    // A few bytes of gzip can declare any size: the data must be able to hold what the header
    // asks before anything is allocated for it (a 1 MB file asked for 3.8 GB, which was
    // allocated, then inflated to the end of the data).
    const auto compressed = static_cast<std::uint64_t>(detail::fileSize(path) - position);
    const std::uint64_t most = detail::maxDeflatedBytes(compressed);
    const auto declared = static_cast<std::uint64_t>(header.layout.dataBytes()) +
                          static_cast<std::uint64_t>(header.byteSkip);
    if (declared > most)
        throw DataError(path + ": truncated data: " + asks +
                        (header.byteSkip > 0 ? " after 'byte skip'" : "") + ", but its " +
                        std::to_string(compressed) + " bytes of gzip data hold at most " +
                        std::to_string(most) + " (deflate expands at most " +
                        std::to_string(detail::kMaxDeflateRatio) + " to 1)");
    detail::GzipInputStream data(in);
    // The data ended (cleanly, or at damage) before the values did.
    const auto ended = [&] {
        const std::string held = std::to_string(
            std::max<std::int64_t>(0, data.decompressedBytes() - header.byteSkip));
        return DataError(path + ": " +
                         (data.failure().empty()
                              ? "truncated data: the gzip data holds only " + held + " bytes"
                              : data.failure() + " after " + held + " bytes") +
                         (header.byteSkip > 0 ? " past 'byte skip'" : "") + "; " + asks);
    };
    data.ignore(static_cast<std::streamsize>(header.byteSkip));
    if (data.gcount() != header.byteSkip)
        throw ended();
    try {
        use({data, path, header.layout, detail::RawOrder::XFastest, fileAxes(header)});
    } catch (const IoError&) {
        throw ended(); // the only reads are from the gzip stream
    }
    if (data.peek() != std::istream::traits_type::eof())
        throw DataError(path + ": data size mismatch: " + asks +
                        ", but the gzip data holds more");
    if (!data.failure().empty())
        throw ended();
}

} // namespace

namespace detail {

void withNrrdData(const std::string& path, const RawDataDecoder& use, const sg::DataRoots* roots) {
    std::ifstream headerFile = openForReading(path);
    const NrrdHeader header = NrrdHeader::parse(headerFile, path);
    std::string dataPath = path;
    std::ifstream detachedFile;
    std::istream* data = &headerFile;
    std::int64_t position = header.dataOffset;
    if (!header.dataFile.empty()) {
        dataPath = dataFilePath(path, header.dataFile);
        if (roots != nullptr)
            roots->check(dataPath, "the NRRD header's data file");
        detachedFile = openForReading(dataPath);
        data = &detachedFile;
        position = 0;
    }
    position += skipLines(*data, dataPath, header.lineSkip);
    const std::string asks = "the header's sizes " + header.sizesText() + " of type '" +
                             header.typeName + "' ask for " +
                             std::to_string(header.layout.dataBytes()) + " bytes";
    if (header.encoding == NrrdEncoding::Raw)
        useRaw(*data, dataPath, header, position, asks, use);
    else
        useGzip(*data, dataPath, header, position, asks, use);
}

} // namespace detail

AnyGrid readNrrdVolume(const std::string& path, const ProgressCallback& progress,
                       const sg::DataRoots* roots) {
    return detail::readRawGrid(
        [&](const detail::RawDataDecoder& use) { detail::withNrrdData(path, use, roots); },
        progress);
}

} // namespace texsplat::volume
