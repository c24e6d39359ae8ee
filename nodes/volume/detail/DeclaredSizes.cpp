#include "nodes/volume/detail/DeclaredSizes.h"

#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"

#include <utility>

namespace texsplat::volume::detail {

DeclaredSizes::DeclaredSizes(const std::string& path, std::string damage)
    : mPath(path), mDamage(std::move(damage)), mIn(openForReading(path)), mEnd(fileSize(path)) {}

bool DeclaredSizes::startsWith(const std::string& magic) {
    std::string start(magic.size(), '\0');
    mIn.read(start.data(), static_cast<std::streamsize>(start.size()));
    mOffset = mIn.gcount();
    return mIn && start == magic;
}

std::uint64_t DeclaredSizes::bigEndian(int bytes, const std::string& what) {
    return read(bytes, true, what);
}

std::uint64_t DeclaredSizes::littleEndian(int bytes, const std::string& what) {
    return read(bytes, false, what);
}

std::uint64_t DeclaredSizes::read(int bytes, bool bigEndian, const std::string& what) {
    need(std::uint64_t(bytes), what);
    std::uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) {
        const auto byte = std::uint64_t(static_cast<unsigned char>(mIn.get()));
        value = bigEndian ? value << 8 | byte : value | byte << (8 * i);
    }
    mOffset += bytes;
    return value;
}

void DeclaredSizes::skip(std::uint64_t bytes, const std::string& what) {
    need(bytes, what);
    mOffset += static_cast<std::int64_t>(bytes);
    mIn.seekg(mOffset);
}

bool DeclaredSizes::seek(std::uint64_t offset) {
    if (offset > std::uint64_t(mEnd))
        return false;
    mOffset = static_cast<std::int64_t>(offset);
    mIn.seekg(mOffset);
    return true;
}

std::uint64_t DeclaredSizes::sized(std::uint64_t items, std::uint64_t each,
                                   const std::string& what) const {
    if (items > std::uint64_t(mEnd - mOffset) / each)
        corrupt(what + " at byte " + std::to_string(mOffset) + " declares " +
                std::to_string(items) + " items of at least " + std::to_string(each) +
                " bytes, but the file ends at byte " + std::to_string(mEnd));
    return items * each;
}

void DeclaredSizes::need(std::uint64_t bytes, const std::string& what) const {
    if (bytes > std::uint64_t(mEnd - mOffset))
        corrupt(what + " at byte " + std::to_string(mOffset) + " needs " + std::to_string(bytes) +
                " bytes, but the file ends at byte " + std::to_string(mEnd));
}

void DeclaredSizes::corrupt(const std::string& what) const {
    throw IoError(mPath + ": " + mDamage + ": " + what);
}

} // namespace texsplat::volume::detail
