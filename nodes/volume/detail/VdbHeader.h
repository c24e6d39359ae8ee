#pragma once

#include <string>

namespace texsplat::volume::detail {

/// @brief Checks the sizes that an OpenVDB file (format 222 and later: OpenVDB 3 on) declares
/// for its strings and metadata (the file's metadata, each grid's descriptor, metadata and
/// transform type) against the bytes the file has, before OpenVDB reads them: OpenVDB allocates
/// and fills a string as long as a damaged length says (2.7 GB from a file of 10 KB, found by
/// fuzz_vdb_reader). Files of older formats, or that are not OpenVDB files, are left to OpenVDB.
/// @throws IoError "path: truncated or corrupt VDB file: a metadata name at byte 57 needs
/// 3806520034 bytes, but the file ends at byte 10175".
void checkVdbHeaderSizes(const std::string& path);

} // namespace texsplat::volume::detail
