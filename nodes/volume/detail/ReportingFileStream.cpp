#include "nodes/volume/detail/ReportingFileStream.h"

#include "nodes/volume/detail/SourceSupport.h"

#include <algorithm>
#include <utility>

namespace texsplat::volume::detail {
namespace {

// Large enough that a grid's many small reads cost little, small enough to keep reports close.
constexpr std::size_t kBufferBytes = std::size_t{1} << 16;

} // namespace

ReportingFileStream::ReportingFileStream(const std::string& path, ProgressCallback progress,
                                         std::string message)
    : std::istream(nullptr), mBuffer(path, std::move(progress), std::move(message)) {
    rdbuf(&mBuffer);
    exceptions(std::ios::badbit);
}

ReportingFileStream::Buffer::Buffer(const std::string& path, ProgressCallback progress,
                                    std::string message)
    : mPath(path), mProgress(std::move(progress)), mMessage(std::move(message)),
      mFile(openForReading(path)), mBytes(kBufferBytes) {
    setg(mBytes.data(), mBytes.data(), mBytes.data());
}

void ReportingFileStream::Buffer::reportRange(std::int64_t first, std::int64_t last) {
    mBegin = first;
    mEnd = std::max(first, last);
    mNextReport = first + kReportBytes;
}

void ReportingFileStream::Buffer::reached(std::int64_t position) {
    if (position < mNextReport || mEnd <= mBegin) {
        return;
    }
    const std::int64_t done = std::min(position, mEnd) - mBegin;
    mNextReport = position + kReportBytes;
    reportProgress(mProgress, mPath, double(done) / double(mEnd - mBegin), mMessage);
}

ReportingFileStream::Buffer::int_type ReportingFileStream::Buffer::underflow() {
    if (gptr() < egptr()) {
        return traits_type::to_int_type(*gptr());
    }
    mBytesStart += egptr() - eback();
    const std::streamsize count =
        mFile.rdbuf()->sgetn(mBytes.data(), static_cast<std::streamsize>(mBytes.size()));
    setg(mBytes.data(), mBytes.data(), mBytes.data() + std::max<std::streamsize>(count, 0));
    if (count <= 0) {
        return traits_type::eof();
    }
    reached(mBytesStart + count);
    return traits_type::to_int_type(*gptr());
}

ReportingFileStream::Buffer::pos_type
ReportingFileStream::Buffer::seekoff(off_type offset, std::ios_base::seekdir direction,
                                     std::ios_base::openmode which) {
    if (direction == std::ios_base::cur) {
        return seekpos(pos_type(mBytesStart + (gptr() - eback()) + offset), which);
    }
    if (direction == std::ios_base::end) {
        std::streambuf& file = *mFile.rdbuf();
        const pos_type end = file.pubseekoff(0, std::ios_base::end, std::ios_base::in);
        // Back to where the buffer ends, which seekpos() takes the file to be.
        if (end == pos_type(off_type(-1)) ||
            file.pubseekpos(pos_type(mBytesStart + (egptr() - eback())), std::ios_base::in) ==
                pos_type(off_type(-1))) {
            return pos_type(off_type(-1));
        }
        return seekpos(end + offset, which);
    }
    return seekpos(pos_type(offset), which);
}

ReportingFileStream::Buffer::pos_type
ReportingFileStream::Buffer::seekpos(pos_type position, std::ios_base::openmode which) {
    const auto target = static_cast<std::int64_t>(off_type(position));
    if (!(which & std::ios_base::in) || target < 0) {
        return pos_type(off_type(-1));
    }
    // Within what is buffered (tellg() comes here too): move in the buffer.
    if (target >= mBytesStart && target <= mBytesStart + (egptr() - eback())) {
        setg(eback(), eback() + (target - mBytesStart), egptr());
        return position;
    }
    if (mFile.rdbuf()->pubseekpos(position, std::ios_base::in) == pos_type(off_type(-1))) {
        return pos_type(off_type(-1));
    }
    mBytesStart = target;
    setg(mBytes.data(), mBytes.data(), mBytes.data());
    return position;
}

} // namespace texsplat::volume::detail
