#include "nodes/volume/detail/GzipInputStream.h"

#include <new>

namespace texsplat::volume::detail {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 18;
// 15: the largest window; +32: zlib recognizes a gzip or a zlib header by itself.
constexpr int kWindowBitsAnyHeader = 15 + 32;

} // namespace

GzipInputStream::GzipInputStream(std::istream& compressed)
    : std::istream(nullptr), mBuffer(compressed) {
    rdbuf(&mBuffer);
}

GzipInputStream::Buffer::Buffer(std::istream& compressed)
    : mIn(compressed), mInput(kBufferBytes), mOutput(kBufferBytes) {
    if (inflateInit2(&mStream, kWindowBitsAnyHeader) != Z_OK)
        throw std::bad_alloc();
}

GzipInputStream::Buffer::~Buffer() { inflateEnd(&mStream); }

bool GzipInputStream::Buffer::refillInput() {
    mIn.read(mInput.data(), static_cast<std::streamsize>(mInput.size()));
    mStream.next_in = reinterpret_cast<Bytef*>(mInput.data());
    mStream.avail_in = static_cast<uInt>(mIn.gcount());
    return mStream.avail_in > 0;
}

GzipInputStream::Buffer::int_type GzipInputStream::Buffer::underflow() {
    while (!mEnded) {
        if (mStream.avail_in == 0 && !refillInput()) {
            mEnded = true;
            if (mStream.total_in > 0 || mDecompressed > 0)
                mFailure = "the gzip data ends early";
            else
                mFailure = "there is no gzip data";
            break;
        }
        mStream.next_out = reinterpret_cast<Bytef*>(mOutput.data());
        mStream.avail_out = static_cast<uInt>(mOutput.size());
        const int status = inflate(&mStream, Z_NO_FLUSH);
        const std::size_t produced = mOutput.size() - mStream.avail_out;
        if (status == Z_STREAM_END) {
            // Another member may follow; only the end of the input ends the data.
            if (mStream.avail_in == 0 && !refillInput())
                mEnded = true;
            else
                inflateReset(&mStream);
        } else if (status != Z_OK && status != Z_BUF_ERROR) {
            mEnded = true;
            mFailure = std::string("the gzip data is damaged (") +
                       (mStream.msg != nullptr ? mStream.msg : zError(status)) + ")";
        }
        if (produced > 0) {
            mDecompressed += static_cast<std::int64_t>(produced);
            setg(mOutput.data(), mOutput.data(), mOutput.data() + produced);
            return traits_type::to_int_type(mOutput[0]);
        }
    }
    return traits_type::eof();
}

} // namespace texsplat::volume::detail
