#include "nodes/volume/detail/VdbTree.h"

#include "nodes/volume/detail/DeclaredSizes.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace texsplat::volume::detail {
namespace {

// The layout OpenVDB 10 reads (tree/Tree.h, RootNode.h, InternalNode.h, LeafNode.h readTopology
// and readBuffers; io/Compression.h readCompressedValues and readData; io/Compression.cc
// unzipFromStream and bloscFromStream), little-endian.
constexpr std::uint32_t kZip = 0x1;
constexpr std::uint32_t kActiveMask = 0x2;
constexpr std::uint32_t kBlosc = 0x4;

// The flag before a node's values: which inactive values and selection mask follow.
constexpr std::int8_t kOneInactiveValue = 2;
constexpr std::int8_t kMaskAndNoInactiveValue = 3;
constexpr std::int8_t kMaskAndOneInactiveValue = 4;
constexpr std::int8_t kMaskAndTwoInactiveValues = 5;
constexpr std::int8_t kAllValues = 6;

constexpr int kUpperLog2Dim = 5;
constexpr int kLowerLog2Dim = 4;
constexpr int kLeafLog2Dim = 3;
constexpr std::uint64_t kCoordBytes = 3 * 4;
constexpr std::uint64_t kBloscHeaderBytes = 16; // version, flags, type size, then three sizes

constexpr std::uint64_t valueCount(int log2Dim) { return std::uint64_t{1} << (3 * log2Dim); }
constexpr std::uint64_t maskBytes(int log2Dim) { return valueCount(log2Dim) / 8; }

using Coord = std::array<std::int32_t, 3>;

std::uint64_t bitsSet(const std::string& mask) {
    std::uint64_t count = 0;
    for (const char byte : mask)
        count += std::uint64_t(__builtin_popcount(static_cast<unsigned char>(byte)));
    return count;
}

class TreeWalk {
public:
    TreeWalk(DeclaredSizes& file, VdbValueSizes values, std::uint32_t compression)
        : mFile(file), mValues(values), mCompression(compression) {}

    VdbNodeCounts walk() {
        mFile.skip(4, "the tree's buffer count");
        mFile.skip(mValues.full, "the tree's background value");
        const std::uint64_t tiles = mFile.littleEndian(4, "the root's tile count");
        const std::uint64_t children = mFile.littleEndian(4, "the root's child count");
        // A tile: its origin, its value and whether it is active.
        mFile.sized(tiles, kCoordBytes + mValues.full + 1, "the root's tiles");
        for (std::uint64_t i = 0; i < tiles; ++i) {
            origin("a root tile's origin");
            mFile.skip(mValues.full + 1, "a root tile's value");
        }
        mFile.sized(children, kCoordBytes + 2 * maskBytes(kUpperLog2Dim) + 1,
                    "the root's child nodes");
        mNodes.rootEntries = tiles + children;
        mNodes.upper = children;
        // OpenVDB keeps the root's children in a map by origin (a repeated origin replaces the
        // child before it) and reads their leaves' values in that map's order: the active voxel
        // count of each leaf, per child, says how many values its block holds.
        std::map<Coord, std::vector<std::uint16_t>> leaves;
        for (std::uint64_t i = 0; i < children; ++i) {
            const Coord childOrigin = origin("a child node's origin");
            std::vector<std::uint16_t> activeVoxels;
            internalTopology(kUpperLog2Dim, activeVoxels);
            leaves[childOrigin] = std::move(activeVoxels);
        }
        for (const auto& child : leaves)
            for (const std::uint16_t active : child.second) {
                mFile.skip(maskBytes(kLeafLog2Dim), "a leaf's value mask");
                values(valueCount(kLeafLog2Dim), active);
            }
        return mNodes;
    }

private:
    // The origin of a root tile or child: OpenVDB writes multiples of the root's child size
    // (4096), so that origin + 4095 is an index; other values overflow its index arithmetic.
    Coord origin(const char* what) {
        const std::uint64_t at = mFile.offset();
        Coord origin;
        for (std::int32_t& axis : origin)
            axis = static_cast<std::int32_t>(mFile.littleEndian(4, what));
        constexpr std::int32_t kRootChildSize = std::int32_t{1} << (kUpperLog2Dim + kLowerLog2Dim +
                                                                    kLeafLog2Dim);
        for (const std::int32_t axis : origin)
            if (axis % kRootChildSize != 0)
                mFile.corrupt(std::string(what) + " at byte " + std::to_string(at) + " is (" +
                              std::to_string(origin[0]) + ", " + std::to_string(origin[1]) + ", " +
                              std::to_string(origin[2]) + "), not a multiple of " +
                              std::to_string(kRootChildSize));
        return origin;
    }

    // An internal node: its child mask, its value mask, its values, then its children.
    void internalTopology(int log2Dim, std::vector<std::uint16_t>& leafActiveVoxels) {
        const std::uint64_t children =
            bitsSet(mFile.bytes(maskBytes(log2Dim), "an internal node's child mask"));
        const std::uint64_t active =
            bitsSet(mFile.bytes(maskBytes(log2Dim), "an internal node's value mask"));
        values(valueCount(log2Dim), active);
        (log2Dim == kLowerLog2Dim ? mNodes.leaves : mNodes.lower) += children;
        for (std::uint64_t i = 0; i < children; ++i) {
            if (log2Dim == kLowerLog2Dim)
                leafActiveVoxels.push_back(static_cast<std::uint16_t>(
                    bitsSet(mFile.bytes(maskBytes(kLeafLog2Dim), "a leaf's value mask"))));
            else
                internalTopology(kLowerLog2Dim, leafActiveVoxels);
        }
    }

    // A node's `count` values (`active` of them active), as readCompressedValues reads them.
    void values(std::uint64_t count, std::uint64_t active) {
        const auto flag = static_cast<std::int8_t>(mFile.littleEndian(1, "a node's value flag"));
        if (flag == kOneInactiveValue || flag == kMaskAndOneInactiveValue ||
            flag == kMaskAndTwoInactiveValues)
            mFile.skip(mValues.full, "a node's inactive value");
        if (flag == kMaskAndTwoInactiveValues)
            mFile.skip(mValues.full, "a node's second inactive value");
        if (flag == kMaskAndNoInactiveValue || flag == kMaskAndOneInactiveValue ||
            flag == kMaskAndTwoInactiveValues)
            mFile.skip(count / 8, "a node's selection mask");
        const std::uint64_t stored =
            (mCompression & kActiveMask) != 0 && flag != kAllValues ? active : count;
        const bool savedAsHalf = mValues.block < mValues.full;
        if (stored == 0 && savedAsHalf)
            return; // OpenVDB's half reader reads nothing, not even a block size, for no value
        const std::uint64_t bytes = stored * mValues.block;
        if ((mCompression & (kZip | kBlosc)) != 0)
            block(bytes);
        else
            mFile.skip(bytes, "a node's values");
    }

    // A zip or blosc block of `bytes` bytes once uncompressed: its size, then its bytes. A size of
    // zero or less is that of a block stored uncompressed, negated, which OpenVDB reads into the
    // node's buffer before comparing the sizes: any other size would overrun the buffer.
    void block(std::uint64_t bytes) {
        const std::uint64_t start = mFile.offset();
        const auto size = static_cast<std::int64_t>(mFile.littleEndian(8, "a block's size"));
        if (size <= 0) {
            const std::uint64_t declared = std::uint64_t{0} - std::uint64_t(size);
            if (declared != bytes)
                mFile.corrupt("an uncompressed block at byte " + std::to_string(start) +
                              " declares " + std::to_string(declared) +
                              " bytes, but its node holds " + std::to_string(bytes));
            mFile.skip(bytes, "an uncompressed block");
        } else if ((mCompression & kBlosc) != 0) {
            checkBloscBlock(mFile, std::uint64_t(size), bytes);
        } else {
            mFile.skip(std::uint64_t(size), "a compressed block");
        }
    }

    DeclaredSizes& mFile;
    VdbValueSizes mValues;
    std::uint32_t mCompression;
    VdbNodeCounts mNodes;
};

} // namespace

void checkBloscBlock(DeclaredSizes& file, std::uint64_t size, std::uint64_t bytes) {
    const std::uint64_t start = file.offset();
    if (size > file.left())
        file.skip(size, "a compressed block"); // refused: the file ends before the block
    if (size < kBloscHeaderBytes)
        file.corrupt("a blosc block at byte " + std::to_string(start) + " of " +
                     std::to_string(size) + " bytes is shorter than its header");
    file.skip(4, "a blosc block's header"); // versions, flags, type size
    const std::uint64_t uncompressed = file.littleEndian(4, "a blosc block's header");
    file.skip(4, "a blosc block's header"); // block size
    const std::uint64_t compressed = file.littleEndian(4, "a blosc block's header");
    // OpenVDB pads what it compresses of fewer than 128 bytes with zeros to 128 (its metadata;
    // blosc refuses to write more than `bytes` into a node's buffer).
    constexpr std::uint64_t kPaddedBytes = 128;
    const bool padded = uncompressed == kPaddedBytes && bytes <= kPaddedBytes;
    if (compressed != size || (uncompressed != bytes && !padded))
        file.corrupt("a blosc block at byte " + std::to_string(start) + " of " +
                     std::to_string(size) + " bytes says it holds " + std::to_string(compressed) +
                     " bytes compressed, " + std::to_string(uncompressed) +
                     " uncompressed, where " + std::to_string(bytes) + " are expected");
    file.skip(size - kBloscHeaderBytes, "a compressed block");
}

VdbNodeCounts checkVdbTree(DeclaredSizes& file, VdbValueSizes values, std::uint32_t compression) {
    return TreeWalk(file, values, compression).walk();
}

} // namespace texsplat::volume::detail
