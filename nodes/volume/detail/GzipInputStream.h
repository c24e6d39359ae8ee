#pragma once

#include <zlib.h>

#include <cstdint>
#include <istream>
#include <streambuf>
#include <string>
#include <vector>

namespace texsplat::volume::detail {

/// @brief The decompressed bytes of gzip (or zlib) data read from another stream, as a
/// std::istream, so that the raw decoder reads compressed files unchanged. Consecutive gzip
/// members are read as one stream, as gunzip does.
///
/// Reading stops at the end of the compressed data or at damage; the stream then reports end of
/// input, and failure() says which: empty after a clean end, else what went wrong ("the gzip data
/// ends early", "the gzip data is damaged (invalid distance too far back)").
class GzipInputStream : public std::istream {
public:
    /// @brief Decompresses what `compressed` holds from its current position on; `compressed`
    /// must outlive this stream.
    explicit GzipInputStream(std::istream& compressed);

    /// @brief Why decompression stopped before the end of the data; empty when it did not.
    const std::string& failure() const { return mBuffer.failure(); }

    /// @brief Bytes decompressed so far (those read and those buffered to be read).
    std::int64_t decompressedBytes() const { return mBuffer.decompressedBytes(); }

private:
    class Buffer : public std::streambuf {
    public:
        explicit Buffer(std::istream& compressed);
        ~Buffer() override;
        Buffer(const Buffer&) = delete;
        Buffer& operator=(const Buffer&) = delete;

        const std::string& failure() const { return mFailure; }
        std::int64_t decompressedBytes() const { return mDecompressed; }

    protected:
        int_type underflow() override;

    private:
        bool refillInput();

        std::istream& mIn;
        z_stream mStream{};
        std::vector<char> mInput;
        std::vector<char> mOutput;
        std::int64_t mDecompressed = 0;
        bool mEnded = false;
        std::string mFailure;
    };

    Buffer mBuffer;
};

} // namespace texsplat::volume::detail
