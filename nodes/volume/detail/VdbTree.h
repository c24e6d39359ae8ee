#pragma once

#include <cstdint>

namespace texsplat::volume::detail {

class DeclaredSizes;

/// @brief How a tree stores its values: `full` bytes each at the root (background, tiles) and for
/// the inactive values of a node, `block` bytes each in the blocks of node values (2 for a float
/// saved as half).
struct VdbValueSizes {
    std::uint64_t full;
    std::uint64_t block;
};

/// @brief The nodes of a tree as OpenVDB reads it, by level: what it allocates for them.
struct VdbNodeCounts {
    std::uint64_t rootEntries = 0; ///< the root's tiles and children, each an entry of its map
    std::uint64_t upper = 0;       ///< internal nodes of 32³ (the root's children)
    std::uint64_t lower = 0;       ///< internal nodes of 16³
    std::uint64_t leaves = 0;      ///< leaves of 8³ values
};

/// @brief Walks an OpenVDB tree of the standard configuration (internal nodes of 32³ and 16³,
/// leaves of 8³) from its start, as OpenVDB reads a grid of format 222 and later: the topology
/// (the root's tiles and children, each node's child and value masks and its values), then the
/// leaves' value blocks. Every count and size the file declares is checked against the bytes the
/// file has before OpenVDB allocates or loops for it: a tile or child count (a damaged count made
/// OpenVDB loop past 10 s at the end of the file), and each block's size (a damaged zip or blosc
/// size became `new char[2^56]`; an uncompressed size other than the node's would overrun its
/// buffer). `compression` is the grid's flags (io::COMPRESS_ZIP, _ACTIVE_MASK, _BLOSC). Leaves
/// that OpenVDB reads in another form than values (bool and mask grids, points) are not walked.
/// @return The nodes OpenVDB makes as it reads the tree: every child read, a repeated origin's
/// too (OpenVDB replaces it in the root's map without deleting it).
/// @throws IoError "path: truncated or corrupt VDB file: grid 'density': a compressed block at
/// byte 8457 needs 72057594037927936 bytes, but the file ends at byte 10175".
VdbNodeCounts checkVdbTree(DeclaredSizes& file, VdbValueSizes values, std::uint32_t compression);

/// @brief Checks a blosc block of `size` bytes at the walk's position that must hold `bytes` once
/// uncompressed, and walks past it. OpenVDB gives blosc the block without its size, and reserves
/// what the block's own header says: the sizes in that header must be the block's and `bytes`
/// (or 128, to which OpenVDB pads fewer bytes).
/// @throws IoError "…: a blosc block at byte 1234 of 95 bytes says it holds 65631 bytes
/// compressed, 2048 uncompressed, where 2048 are expected".
void checkBloscBlock(DeclaredSizes& file, std::uint64_t size, std::uint64_t bytes);

} // namespace texsplat::volume::detail
