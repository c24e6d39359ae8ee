#include "nodes/volume/detail/VdbHeader.h"

#include "nodes/volume/detail/DeclaredSizes.h"

#include <cstdint>
#include <string>
#include <vector>

namespace texsplat::volume::detail {
namespace {

// The layout OpenVDB 10 writes and reads (io/Archive.cc, io/File.cc, io/GridDescriptor.cc,
// Metadata.cc, MetaMap.cc), little-endian: a header, the file's metadata, the grid count, then
// per grid a descriptor (name, type, instance parent, and the positions of the grid, its voxel
// buffers and its end) followed by the grid (compression flags, metadata, transform, tree).
constexpr std::uint32_t kFirstCheckedVersion = 222; // per-grid compression flags
constexpr std::uint32_t kUuidLength = 36;           // the UUID as text

class VdbWalk {
public:
    explicit VdbWalk(DeclaredSizes& file) : mFile(file) {}

    void walk() {
        const std::uint64_t version = mFile.littleEndian(4, "the file version");
        if (version < kFirstCheckedVersion)
            return;
        mFile.skip(8, "the library version");
        const bool hasGridOffsets = mFile.littleEndian(1, "the grid offsets flag") != 0;
        mFile.skip(kUuidLength, "the file's UUID");
        metadata("the file's metadata");
        if (!hasGridOffsets)
            return; // grids without descriptors: OpenVDB reads them as a stream
        const std::uint64_t grids = mFile.littleEndian(4, "the grid count");
        mFile.sized(grids, 3 * 4 + 3 * 8, "the grid descriptors");
        for (std::uint64_t i = 0; i < grids; ++i) {
            text("a grid's name");
            text("a grid's type");
            text("a grid's instance parent");
            const std::uint64_t grid = mFile.littleEndian(8, "a grid's position");
            mFile.skip(8, "a grid's buffer position");
            const std::uint64_t end = mFile.littleEndian(8, "a grid's end");
            if (!mFile.seek(grid))
                return;
            mFile.skip(4, "a grid's compression flags");
            metadata("a grid's metadata");
            text("a grid's transform type");
            if (!mFile.seek(end))
                return;
        }
    }

private:
    // A string: its length (4 bytes), then its bytes.
    void text(const std::string& what) {
        mFile.skip(mFile.littleEndian(4, what + "'s length"), what);
    }

    // A MetaMap: a count, then per item its name, its type name, its value's size and the value.
    void metadata(const std::string& what) {
        const std::uint64_t items = mFile.littleEndian(4, what);
        mFile.sized(items, 3 * 4, what);
        for (std::uint64_t i = 0; i < items; ++i) {
            text("a metadata name");
            text("a metadata type");
            mFile.skip(mFile.littleEndian(4, "a metadata value's size"), "a metadata value");
        }
    }

    DeclaredSizes& mFile;
};

} // namespace

void checkVdbHeaderSizes(const std::string& path) {
    DeclaredSizes file(path, "truncated or corrupt VDB file");
    if (file.startsWith(std::string(" BDV\0\0\0\0", 8)))
        VdbWalk(file).walk();
}

} // namespace texsplat::volume::detail
