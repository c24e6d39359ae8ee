#pragma once

#include "nodes/volume/detail/VdbTree.h"

#include <cstdint>
#include <map>
#include <string>

namespace texsplat::volume::detail {

/// @brief A grid's tree as the walk found it: its nodes and what OpenVDB allocates to read them
/// (vdbTreeBytes()).
struct VdbTreeSize {
    VdbNodeCounts nodes;
    std::uint64_t bytes = 0;
};

/// @brief The trees of a file that checkVdbDeclaredSizes() walked.
struct VdbFileTrees {
    /// By grid name, without the suffix OpenVDB gives a repeated name (the largest tree of the
    /// grids so named); an instance grid has its parent's. Bool, mask and point grids are absent.
    std::map<std::string, VdbTreeSize> grids;
    /// Written as a stream: OpenVDB reads every tree when it opens the file.
    bool streamed = false;

    /// @brief The tree of the grid OpenVDB reads for `gridName` (a name, or a name with the
    /// suffix of a repeated one), or nullptr for a grid whose tree was not walked.
    const VdbTreeSize* find(const std::string& gridName) const;
};

/// @brief Walks an OpenVDB file (format 222 and later: OpenVDB 3 on) as OpenVDB 10 reads it,
/// checking every size and count it declares against the bytes the file has before OpenVDB
/// allocates or loops for them: the file's metadata, each grid's descriptor and the positions it
/// gives, each grid's metadata, transform and tree (VdbTree.h). OpenVDB allocated and filled a
/// string as long as a damaged length said (2.7 GB from a file of 10 KB), a block as large as a
/// damaged size said, and looped over a damaged tile count (found by fuzz_vdb_reader). Files
/// that are not OpenVDB files are left to OpenVDB.
/// @throws IoError "path: truncated or corrupt VDB file: a metadata name at byte 57 needs
/// 3806520034 bytes, but the file ends at byte 10175", with the grid named where one is being
/// walked; "path: VDB file format 221 is older than 222 …" for older formats.
/// @return The trees walked; none for a file that is not an OpenVDB file.
VdbFileTrees checkVdbDeclaredSizes(const std::string& path);

} // namespace texsplat::volume::detail
