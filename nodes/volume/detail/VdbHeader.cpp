#include "nodes/volume/detail/VdbHeader.h"

#include "nodes/volume/detail/DeclaredSizes.h"
#include "nodes/volume/detail/Printable.h"
#include "nodes/volume/detail/VdbTree.h"
#include "nodes/volume/detail/VdbTreeMemory.h"
#include "scenegraph/Error.h"

#include <openvdb/Metadata.h>
#include <openvdb/io/DelayedLoadMetadata.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::volume::detail {
namespace {

// The layout OpenVDB 10 writes and reads (io/Archive.cc, io/File.cc, io/GridDescriptor.cc,
// Metadata.cc, MetaMap.cc, math/Transform.cc, math/Maps.h), little-endian: a header, the file's
// metadata, the grid count, then per grid a descriptor (name, type, instance parent, and the
// positions of the grid, its voxel buffers and its end) followed by the grid (compression flags,
// metadata, transform, tree). A file written as a stream has no positions: OpenVDB reads all its
// grids, trees included, when it opens the file.
constexpr std::uint32_t kFirstCheckedVersion = 222; // per-grid compression flags
constexpr std::uint32_t kUuidLength = 36;           // the UUID as text
constexpr std::string_view kHalfFloatSuffix = "_HalfFloat"; // a grid type saved as half floats
constexpr char kUniqueNameSeparator = '\x1e';       // "name\x1e1": the second grid named "name"

// A tree whose leaves hold values (not a bool, mask or point grid's): the bytes of a value in full
// and as a half float where OpenVDB saves one so, and what OpenVDB allocates to read it.
struct TreeType {
    VdbValueSizes values;
    std::uint64_t (*bytes)(const VdbNodeCounts&);
};

std::optional<TreeType> treeType(std::string type) {
    const bool half = type.size() > kHalfFloatSuffix.size() &&
                      type.compare(type.size() - kHalfFloatSuffix.size(), std::string::npos,
                                   kHalfFloatSuffix) == 0;
    if (half)
        type.erase(type.size() - kHalfFloatSuffix.size());
    const std::map<std::string, TreeType> trees = {
        {"Tree_float_5_4_3", {{4, half ? 2u : 4u}, &vdbTreeBytes<openvdb::FloatTree>}},
        {"Tree_double_5_4_3", {{8, half ? 2u : 8u}, &vdbTreeBytes<openvdb::DoubleTree>}},
        {"Tree_vec3s_5_4_3", {{12, half ? 6u : 12u}, &vdbTreeBytes<openvdb::Vec3STree>}},
        {"Tree_vec3d_5_4_3", {{24, half ? 6u : 24u}, &vdbTreeBytes<openvdb::Vec3DTree>}},
        {"Tree_int32_5_4_3", {{4, 4}, &vdbTreeBytes<openvdb::Int32Tree>}},
        {"Tree_int64_5_4_3", {{8, 8}, &vdbTreeBytes<openvdb::Int64Tree>}},
        {"Tree_vec3i_5_4_3", {{12, 12}, &vdbTreeBytes<openvdb::Vec3ITree>}}};
    const auto found = trees.find(type);
    return found == trees.end() ? std::nullopt : std::optional(found->second);
}

// The bytes that each kind of transform map holds after its type name (math/Maps.h: a matrix of
// 16 doubles, or vectors of 3 doubles).
std::optional<std::uint64_t> mapBytes(const std::string& type) {
    const std::map<std::string, std::uint64_t> maps = {
        {"AffineMap", 128},         {"UnitaryMap", 128}, {"ScaleMap", 5 * 24},
        {"UniformScaleMap", 5 * 24}, {"TranslationMap", 24}, {"ScaleTranslateMap", 6 * 24},
        {"UniformScaleTranslateMap", 6 * 24}};
    const auto found = maps.find(type);
    return found == maps.end() ? std::nullopt : std::optional(found->second);
}

std::string baseName(const std::string& name) {
    return name.substr(0, name.find(kUniqueNameSeparator));
}

struct Descriptor {
    std::string name;
    std::string type;
    std::string instanceParent;
};

class VdbWalk {
public:
    VdbWalk(DeclaredSizes& file, const std::string& path) : mFile(file), mPath(path) {}

    VdbFileTrees walk() {
        const std::uint64_t version = mFile.littleEndian(4, "the file version");
        if (version < kFirstCheckedVersion)
            throw IoError(mPath + ": VDB file format " + std::to_string(version) +
                          " is older than 222 (OpenVDB 3), which texsplat cannot check before "
                          "OpenVDB reads it; write the file again with a newer OpenVDB");
        mFile.skip(8, "the library version");
        const bool hasGridOffsets = mFile.littleEndian(1, "the grid offsets flag") != 0;
        mTrees.streamed = !hasGridOffsets;
        uuid();
        metadata("the file's metadata");
        const std::uint64_t grids = mFile.littleEndian(4, "the grid count");
        mFile.sized(grids, 3 * 4 + 3 * 8, "the grid descriptors");
        std::vector<Descriptor> descriptors;
        for (std::uint64_t i = 0; i < grids; ++i) {
            const Descriptor grid{text("a grid's name"), text("a grid's type"),
                                  text("a grid's instance parent")};
            mFile.setContext("grid '" + printable(grid.name) + "'");
            const std::uint64_t start = mFile.littleEndian(8, "its position");
            mFile.skip(8, "its buffers' position");
            const std::uint64_t end = mFile.littleEndian(8, "its end");
            const std::uint64_t fileEnd = mFile.offset() + mFile.left();
            const std::string placed = "its descriptor places it from byte " +
                                       std::to_string(start) + " to byte " + std::to_string(end);
            if (hasGridOffsets && end > fileEnd)
                mFile.corrupt(placed + ", but the file ends at byte " + std::to_string(fileEnd));
            if (hasGridOffsets && (start < mFile.offset() || start > end))
                mFile.corrupt(placed + ", not after the descriptor, which ends at byte " +
                              std::to_string(mFile.offset()));
            if (hasGridOffsets)
                mFile.seek(start);
            // A transform OpenVDB does not know: it reports that itself, when it opens a stream
            // or lists this grid; the other grids of a file with positions are read on their own.
            if (!gridData(grid, !hasGridOffsets) && !hasGridOffsets)
                return mTrees;
            if (hasGridOffsets)
                mFile.seek(end);
            mFile.setContext("");
            descriptors.push_back(grid);
        }
        checkInstances(descriptors);
        return mTrees;
    }

private:
    // A grid's compression flags, metadata, transform and tree; false where OpenVDB cannot read
    // the transform, which it reports itself. `streamed`: OpenVDB reads the tree on opening.
    bool gridData(const Descriptor& grid, bool streamed) {
        const auto compression =
            static_cast<std::uint32_t>(mFile.littleEndian(4, "its compression flags"));
        metadata("its metadata");
        if (!transform(text("its transform type")))
            return false;
        if (!grid.instanceParent.empty())
            return true; // its parent's tree, walked as that grid
        const std::optional<TreeType> tree = treeType(grid.type);
        if (tree) {
            const VdbNodeCounts nodes = checkVdbTree(mFile, tree->values, compression);
            keepLargest(baseName(grid.name), {nodes, tree->bytes(nodes)});
        } else if (streamed)
            throw IoError(mPath + ": grid '" + printable(grid.name) + "' is a " +
                          printable(grid.type) +
                          " grid in a VDB file written as a stream, which OpenVDB reads whole "
                          "on opening it; texsplat checks only grids of float, double, integer "
                          "and vector values before that");
        // Other grids are read only when asked for, and readVdbGrid() refuses their type first.
        return true;
    }

    // A transform: its map's type name, then the map; false for a type OpenVDB does not know.
    bool transform(const std::string& type) {
        if (const std::optional<std::uint64_t> bytes = mapBytes(type)) {
            mFile.skip(*bytes, "its transform");
            return true;
        }
        if (type != "NonlinearFrustumMap")
            return false;
        // A frustum: its box (6 doubles), taper and depth, then a linear map of its own.
        mFile.skip(8 * 8, "its frustum transform");
        const std::string second = text("its frustum's second map type");
        if (second == type)
            mFile.corrupt("its frustum transform holds a frustum transform");
        return transform(second);
    }

    // A grid that shares the tree of another is read with that grid's tree, walked under the
    // other grid's type: the types must be the same, as OpenVDB writes them.
    void checkInstances(const std::vector<Descriptor>& descriptors) {
        for (const Descriptor& instance : descriptors)
            for (const Descriptor& parent : descriptors) {
                if (instance.instanceParent.empty() ||
                    baseName(parent.name) != baseName(instance.instanceParent))
                    continue;
                if (parent.type != instance.type)
                    mFile.corrupt("grid '" + printable(instance.name) + "' of type " +
                                  printable(instance.type) + " shares the tree of grid '" +
                                  printable(parent.name) + "' of type " + printable(parent.type));
                const auto tree = mTrees.grids.find(baseName(parent.name));
                if (tree != mTrees.grids.end())
                    keepLargest(baseName(instance.name), VdbTreeSize(tree->second));
            }
    }

    // OpenVDB reads the first of the grids of one name that it finds: count the largest.
    void keepLargest(const std::string& name, const VdbTreeSize& tree) {
        VdbTreeSize& kept = mTrees.grids[name];
        if (tree.bytes > kept.bytes)
            kept = tree;
    }

    // The file's UUID, which OpenVDB reads as text (`is >> uuid`, Boost's formatted input): 32
    // hex digits and 4 hyphens, 8-4-4-4-12, each after any whitespace, which it skips. A walk
    // that took the 36 bytes a writer puts there would read the rest one byte off OpenVDB's where
    // a damaged UUID holds a space (a string length read from the wrong bytes: OpenVDB allocated
    // 1.4 GB, found by fuzz_vdb_reader). What Boost would fail on, OpenVDB would then read from
    // a failed stream: refused here instead.
    void uuid() {
        const std::uint64_t start = mFile.offset();
        for (std::size_t i = 0; i < kUuidLength; ++i) {
            char c = 0;
            do {
                c = static_cast<char>(mFile.littleEndian(1, "the file's UUID"));
            } while (c == ' ' || (c >= '\t' && c <= '\r'));
            const bool hyphen = i == 8 || i == 13 || i == 18 || i == 23;
            const bool hex = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
            if (hyphen ? c != '-' : !hex)
                mFile.corrupt("the file's UUID at byte " + std::to_string(start) +
                              " is not one (8-4-4-4-12 hex digits)");
        }
    }

    // A string: its length (4 bytes), then its bytes.
    std::string text(const std::string& what) {
        return mFile.bytes(mFile.littleEndian(4, what + "'s length"), what);
    }

    // A MetaMap: a count, then per item its name, its type name, its value's size and the value.
    // OpenVDB reads a value of a type it knows as that type does, whatever the size says: a
    // fixed number of bytes, a string of that size, or the delayed-load metadata's own layout.
    void metadata(const std::string& what) {
        const std::uint64_t items = mFile.littleEndian(4, what);
        mFile.sized(items, 3 * 4, what);
        for (std::uint64_t i = 0; i < items; ++i) {
            mFile.skip(mFile.littleEndian(4, "a metadata name's length"), "a metadata name");
            const std::string type = text("a metadata type");
            const std::uint64_t size = mFile.littleEndian(4, "a metadata value's size");
            if (type == openvdb::io::DelayedLoadMetadata::staticTypeName())
                delayedLoadMetadata(size);
            else if (type != "string" && openvdb::Metadata::isRegisteredType(type))
                mFile.skip(openvdb::Metadata::createMetadata(type)->size(), "a metadata value");
            else
                mFile.skip(size, "a metadata value");
        }
    }

    // What OpenVDB writes in every grid for delayed loading (io/DelayedLoadMetadata.cc): a leaf
    // count, a mask of a byte per leaf and a compressed size of 8 bytes per leaf, each a blosc
    // block or stored as it is (after a size of 0; all ones: no compressed sizes), then whatever
    // the value's size says more. OpenVDB reserves and fills what the count and the blosc headers
    // say.
    void delayedLoadMetadata(std::uint64_t size) {
        if (size == 0)
            return;
        constexpr std::uint64_t kMinLeafBytes = 64; // a leaf's value mask
        constexpr std::uint64_t kNoSizes = 0xffffffff;
        const std::uint64_t start = mFile.offset();
        const std::uint64_t leaves = mFile.littleEndian(4, "the delayed-load metadata's count");
        mFile.sized(leaves, kMinLeafBytes, "the delayed-load metadata's leaves");
        const std::uint64_t maskBytes = mFile.littleEndian(4, "the delayed-load mask's size");
        if (maskBytes > 0)
            checkBloscBlock(mFile, maskBytes, leaves);
        else
            mFile.skip(leaves, "the delayed-load mask");
        const std::uint64_t sizesBytes = mFile.littleEndian(4, "the delayed-load sizes' size");
        if (sizesBytes > 0 && sizesBytes != kNoSizes)
            checkBloscBlock(mFile, sizesBytes, 8 * leaves);
        else if (sizesBytes == 0)
            mFile.skip(8 * leaves, "the delayed-load sizes");
        const std::uint64_t read = mFile.offset() - start;
        if (read < size)
            mFile.skip(size - read, "a metadata value");
    }

    DeclaredSizes& mFile;
    const std::string& mPath;
    VdbFileTrees mTrees;
};

} // namespace

const VdbTreeSize* VdbFileTrees::find(const std::string& gridName) const {
    const auto found = grids.find(baseName(gridName));
    return found == grids.end() ? nullptr : &found->second;
}

VdbFileTrees checkVdbDeclaredSizes(const std::string& path) {
    DeclaredSizes file(path, "truncated or corrupt VDB file");
    if (file.startsWith(std::string(" BDV\0\0\0\0", 8)))
        return VdbWalk(file, path).walk();
    return {};
}

} // namespace texsplat::volume::detail
