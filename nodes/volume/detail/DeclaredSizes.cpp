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

std::uint64_t DeclaredSizes::bigEndian(int bytes, std::string_view what) {
    return read(bytes, true, what);
}

std::uint64_t DeclaredSizes::littleEndian(int bytes, std::string_view what) {
    return read(bytes, false, what);
}

std::uint64_t DeclaredSizes::read(int bytes, bool bigEndian, std::string_view what) {
    need(std::uint64_t(bytes), what);
    std::uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) {
        const auto byte = std::uint64_t(static_cast<unsigned char>(mIn.get()));
        value = bigEndian ? value << 8 | byte : value | byte << (8 * i);
    }
    mOffset += bytes;
    return value;
}

std::string DeclaredSizes::bytes(std::uint64_t count, std::string_view what) {
    need(count, what);
    std::string bytes(count, '\0');
    mIn.read(bytes.data(), static_cast<std::streamsize>(count));
    mOffset += static_cast<std::int64_t>(count);
    return bytes;
}

void DeclaredSizes::skip(std::uint64_t bytes, std::string_view what) {
    // A tree has millions of small fields to skip: reading past them keeps to the stream's
    // buffer, where a seek would ask the system each time.
    constexpr std::uint64_t kMaxIgnored = 4096;
    need(bytes, what);
    mOffset += static_cast<std::int64_t>(bytes);
    if (bytes <= kMaxIgnored)
        mIn.ignore(static_cast<std::streamsize>(bytes));
    else
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
                                   std::string_view what) const {
    if (items > std::uint64_t(mEnd - mOffset) / each)
        corrupt(std::string(what) + " at byte " + std::to_string(mOffset) + " declares " +
                std::to_string(items) + " items of at least " + std::to_string(each) +
                " bytes, but the file ends at byte " + std::to_string(mEnd));
    return items * each;
}

void DeclaredSizes::need(std::uint64_t bytes, std::string_view what) const {
    if (bytes > std::uint64_t(mEnd - mOffset))
        corrupt(std::string(what) + " at byte " + std::to_string(mOffset) + " needs " +
                std::to_string(bytes) +
                " bytes, but the file ends at byte " + std::to_string(mEnd));
}

void DeclaredSizes::corrupt(std::string_view what) const {
    throw IoError(mPath + ": " + mDamage + ": " + (mContext.empty() ? "" : mContext + ": ") +
                  std::string(what));
}

} // namespace texsplat::volume::detail
