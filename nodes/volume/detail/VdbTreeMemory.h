#pragma once

#include "nodes/volume/detail/VdbTree.h"
#include "scenegraph/MemoryLimit.h"

#include <openvdb/openvdb.h>

#include <cstdint>
#include <utility>

namespace texsplat::volume::detail {

/// @brief The bytes OpenVDB allocates to read a tree of type `TreeT` (openvdb::FloatTree, …)
/// whose nodes are `nodes`, from the sizes of its own node types (OpenVDB 10, 64-bit: a float
/// tree's internal nodes of 32³ take 264 KiB each, of 16³ 33 KiB, a leaf 96 bytes and 2 KiB of
/// values; a vec3s tree's twice and three times that), so that a grid is refused before OpenVDB
/// reads it: a file of N bytes may make it allocate about 32 N (64 N for vec3s). Each allocation
/// counts glibc's header and rounding, each root entry a node of its std::map, and reading an
/// internal node of 32³ holds up to three arrays of its values at a time.
/// The sum saturates (byteSum(), byteProduct()).
template <class TreeT> std::uint64_t vdbTreeBytes(const VdbNodeCounts& nodes) {
    using Value = typename TreeT::ValueType;
    using Upper = typename TreeT::RootNodeType::ChildNodeType;
    using Lower = typename Upper::ChildNodeType;
    using Leaf = typename Lower::ChildNodeType;
    constexpr std::uint64_t kAllocation = 16;           // glibc: 8 bytes of header, 16-aligned
    constexpr std::uint64_t kMapNode = 4 * sizeof(void*); // libstdc++'s colour, parent, children
    // RootNode's private NodeStruct: a child pointer, then a tile (its value and active flag).
    struct Tile {
        Value value;
        bool active;
    };
    struct NodeStruct {
        void* child;
        Tile tile;
    };
    constexpr std::uint64_t rootEntry =
        kMapNode + sizeof(std::pair<const openvdb::Coord, NodeStruct>) + kAllocation;
    constexpr std::uint64_t leaf =
        sizeof(Leaf) + kAllocation + Leaf::SIZE * sizeof(Value) + kAllocation;
    const std::uint64_t reading = nodes.upper > 0 ? 3 * Upper::NUM_VALUES * sizeof(Value) : 0;
    std::uint64_t bytes = sizeof(TreeT) + kAllocation + reading;
    bytes = byteSum(bytes, byteProduct(nodes.rootEntries, rootEntry));
    bytes = byteSum(bytes, byteProduct(nodes.upper, sizeof(Upper) + kAllocation));
    bytes = byteSum(bytes, byteProduct(nodes.lower, sizeof(Lower) + kAllocation));
    return byteSum(bytes, byteProduct(nodes.leaves, leaf));
}

} // namespace texsplat::volume::detail
