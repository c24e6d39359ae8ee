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

AnyGrid readRaw(std::istream& in, const std::string& path, const NrrdHeader& header,
                std::int64_t position, const std::string& asks, const ProgressCallback& progress) {
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
    return detail::readRawData(in, path, header.layout, detail::RawOrder::XFastest, progress,
                               fileAxes(header));
}

AnyGrid readGzip(std::istream& in, const std::string& path, const NrrdHeader& header,
                 const std::string& asks, const ProgressCallback& progress) {
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
    AnyGrid grid;
    try {
        grid = detail::readRawData(data, path, header.layout, detail::RawOrder::XFastest,
                                   progress, fileAxes(header));
    } catch (const IoError&) {
        throw ended(); // the only reads are from the gzip stream
    }
    if (data.peek() != std::istream::traits_type::eof())
        throw DataError(path + ": data size mismatch: " + asks +
                        ", but the gzip data holds more");
    if (!data.failure().empty())
        throw ended();
    return grid;
}

} // namespace

AnyGrid readNrrdVolume(const std::string& path, const ProgressCallback& progress) {
    std::ifstream headerFile = detail::openForReading(path);
    const NrrdHeader header = NrrdHeader::parse(headerFile, path);
    std::string dataPath = path;
    std::ifstream detachedFile;
    std::istream* data = &headerFile;
    std::int64_t position = header.dataOffset;
    if (!header.dataFile.empty()) {
        dataPath = dataFilePath(path, header.dataFile);
        detachedFile = detail::openForReading(dataPath);
        data = &detachedFile;
        position = 0;
    }
    position += skipLines(*data, dataPath, header.lineSkip);
    const std::string asks = "the header's sizes " + header.sizesText() + " of type '" +
                             header.typeName + "' ask for " +
                             std::to_string(header.layout.dataBytes()) + " bytes";
    return header.encoding == NrrdEncoding::Raw
               ? readRaw(*data, dataPath, header, position, asks, progress)
               : readGzip(*data, dataPath, header, asks, progress);
}

} // namespace texsplat::volume
