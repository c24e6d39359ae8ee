#include "nodes/volume/detail/Hdf5GlobalHeaps.h"

#include "scenegraph/Error.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string_view>
#include <vector>

namespace texsplat::volume::detail {
namespace {

constexpr std::string_view kSuperblockSignature = "\x89HDF\r\n\x1a\n";
constexpr std::string_view kCollectionSignature = "GCOL";

std::uint64_t littleEndian(const char* bytes, int count) {
    std::uint64_t value = 0;
    for (int i = count - 1; i >= 0; --i)
        value = (value << 8U) | static_cast<unsigned char>(bytes[i]);
    return value;
}

// The "size of lengths" of the superblock at byte 0, 512, 1024, ... (HDF5's file format
// specification, "Superblock"), 8 where it is not one of 2, 4, 8; none without a superblock.
std::optional<int> sizeOfLengths(std::ifstream& in, std::uint64_t fileSize) {
    std::array<char, 16> head{};
    for (std::uint64_t at = 0; at + head.size() <= fileSize; at = at == 0 ? 512 : at * 2) {
        in.seekg(static_cast<std::streamoff>(at));
        if (!in.read(head.data(), head.size()))
            break;
        if (std::string_view(head.data(), kSuperblockSignature.size()) != kSuperblockSignature)
            continue;
        const int version = static_cast<unsigned char>(head[8]);
        const int lengths = static_cast<unsigned char>(version >= 2 ? head[10] : head[14]);
        return lengths == 2 || lengths == 4 || lengths == 8 ? lengths : 8;
    }
    return std::nullopt;
}

// Walks the collection at `start` as HDF5 1.10 does; throws where it would not move on.
void walkCollection(std::ifstream& in, std::uint64_t start, std::uint64_t fileSize,
                    int lengths, const std::string& path) {
    std::vector<char> header(8 + static_cast<std::size_t>(lengths));
    in.clear();
    in.seekg(static_cast<std::streamoff>(start));
    if (!in.read(header.data(), static_cast<std::streamsize>(header.size())) || header[4] != 1)
        return; // not a collection HDF5 reads (version 1)
    const std::uint64_t size = littleEndian(header.data() + 8, lengths);
    const std::uint64_t end = start + std::min(size, fileSize - start);
    const std::uint64_t objectHeader = 8 + static_cast<std::uint64_t>(lengths);
    std::uint64_t at = start + header.size();
    std::vector<char> object(static_cast<std::size_t>(objectHeader));
    while (at < end && at + objectHeader <= end) {
        in.seekg(static_cast<std::streamoff>(at));
        if (!in.read(object.data(), static_cast<std::streamsize>(object.size())))
            return;
        const std::uint64_t index = littleEndian(object.data(), 2);
        const std::uint64_t bytes = littleEndian(object.data() + 8, lengths);
        if (index == 0 && bytes == 0)
            throw IoError(path + ": truncated or corrupt NetCDF file: the HDF5 global heap at byte " +
                          std::to_string(start) + " has a free-space object of 0 bytes at byte " +
                          std::to_string(at) + ", which HDF5 1.10 reads forever");
        // An object is its header and its data padded to 8 bytes; the free space, its size.
        const std::uint64_t step = index > 0 ? objectHeader + ((bytes + 7) / 8) * 8 : bytes;
        if (step < bytes || step > end - at)
            return; // past the collection: HDF5 stops there too
        at += step;
    }
}

} // namespace

void checkHdf5GlobalHeaps(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        return;
    const auto fileSize = static_cast<std::uint64_t>(in.tellg());
    const std::optional<int> lengths = sizeOfLengths(in, fileSize);
    if (!lengths)
        return; // not HDF5
    in.clear();
    in.seekg(0);
    // Scanned in chunks that overlap by the signature's length less one byte.
    constexpr std::size_t kChunk = std::size_t{1} << 20;
    const std::size_t overlap = kCollectionSignature.size() - 1;
    std::vector<char> chunk(kChunk + overlap);
    std::vector<std::uint64_t> collections;
    std::uint64_t chunkStart = 0;
    std::size_t carried = 0;
    while (in) {
        in.read(chunk.data() + carried, static_cast<std::streamsize>(kChunk));
        const std::size_t filled = carried + static_cast<std::size_t>(in.gcount());
        const std::string_view text(chunk.data(), filled);
        for (std::size_t at = text.find(kCollectionSignature); at != std::string_view::npos;
             at = text.find(kCollectionSignature, at + 1))
            collections.push_back(chunkStart + at);
        if (filled <= overlap)
            break;
        std::copy(chunk.begin() + static_cast<std::ptrdiff_t>(filled - overlap),
                  chunk.begin() + static_cast<std::ptrdiff_t>(filled), chunk.begin());
        chunkStart += filled - overlap;
        carried = overlap;
    }
    for (const std::uint64_t start : collections)
        walkCollection(in, start, fileSize, *lengths, path);
}

} // namespace texsplat::volume::detail
