#include "nodes/volume/NpyVolume.h"

#include "nodes/volume/NpyHeader.h"
#include "nodes/volume/detail/RawData.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"

#include <fstream>

namespace texsplat::volume {

namespace detail {

void withNpyData(const std::string& path, const RawDataDecoder& use) {
    std::ifstream in = openForReading(path);
    const NpyHeader header = NpyHeader::parse(in, path);
    const std::int64_t available = fileSize(path) - header.dataOffset;
    const std::int64_t needed = header.layout.dataBytes();
    const std::string asks = "the header's shape " + header.shapeText() + " of '" + header.descr +
                             "' asks for " + std::to_string(needed) + " bytes";
    if (available < needed)
        throw DataError(path + ": truncated data: " + asks + ", but only " +
                        std::to_string(available) + " bytes follow it");
    if (available > needed)
        throw DataError(path + ": data size mismatch: " + asks + ", but " +
                        std::to_string(available) + " bytes follow it");
    use({in, path, header.layout, header.fortranOrder ? RawOrder::ZFastest : RawOrder::XFastest,
         {}});
}

} // namespace detail

AnyGrid readNpyVolume(const std::string& path, const ProgressCallback& progress) {
    return detail::readRawGrid(
        [&](const detail::RawDataDecoder& use) { detail::withNpyData(path, use); }, progress);
}

} // namespace texsplat::volume
