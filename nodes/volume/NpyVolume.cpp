#include "nodes/volume/NpyVolume.h"

#include "nodes/volume/NpyHeader.h"
#include "nodes/volume/detail/RawData.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"

#include <fstream>

namespace texsplat::volume {

AnyGrid readNpyVolume(const std::string& path, const ProgressCallback& progress) {
    std::ifstream in = detail::openForReading(path);
    const NpyHeader header = NpyHeader::parse(in, path);
    const std::int64_t fileSize = detail::fileSize(path);
    const std::int64_t available = fileSize - header.dataOffset;
    const std::int64_t needed = header.layout.dataBytes();
    const std::string asks = "the header's shape " + header.shapeText() + " of '" + header.descr +
                             "' asks for " + std::to_string(needed) + " bytes";
    if (available < needed)
        throw DataError(path + ": truncated data: " + asks + ", but only " +
                        std::to_string(available) + " bytes follow it");
    if (available > needed)
        throw DataError(path + ": data size mismatch: " + asks + ", but " +
                        std::to_string(available) + " bytes follow it");
    return detail::readRawData(in, path, header.layout,
                               header.fortranOrder ? detail::RawOrder::ZFastest
                                                   : detail::RawOrder::XFastest,
                               progress);
}

} // namespace texsplat::volume
