#pragma once

#include "nodes/volume/Progress.h"

#include <cstdint>
#include <fstream>
#include <istream>
#include <streambuf>
#include <string>
#include <vector>

namespace texsplat::volume::detail {

/// @brief A file as a seekable std::istream that tells a ProgressCallback how much of a byte range
/// has been read: for a library that reads a whole grid from a stream in one call (OpenVDB), the
/// only place to see its progress and to stop it.
///
/// Each time reading passes a further kReportBytes into the range set by reportRange(), the
/// callback is told `message` and the fraction of the range read so far. When it answers false,
/// reportProgress() throws LoadCancelled out of the buffer; the stream sets its exception mask
/// for badbit, so the exception leaves the reading library instead of being turned into a failed
/// read. The callback is called on the thread that reads.
class ReportingFileStream : public std::istream {
public:
    /// @brief Reads are reported no more often than every this many bytes.
    static constexpr std::int64_t kReportBytes = std::int64_t{1} << 20;

    /// @brief Opens `path` for reading.
    /// @throws IoError as openForReading().
    ReportingFileStream(const std::string& path, ProgressCallback progress, std::string message);

    /// @brief From now on, reports reads between file offsets `first` and `last` as the fraction
    /// of that range read.
    void reportRange(std::int64_t first, std::int64_t last) { mBuffer.reportRange(first, last); }

private:
    class Buffer : public std::streambuf {
    public:
        Buffer(const std::string& path, ProgressCallback progress, std::string message);

        void reportRange(std::int64_t first, std::int64_t last);

    protected:
        int_type underflow() override;
        pos_type seekoff(off_type offset, std::ios_base::seekdir direction,
                         std::ios_base::openmode which) override;
        pos_type seekpos(pos_type position, std::ios_base::openmode which) override;

    private:
        // Reports that the file has been read up to `position` when that is far enough on.
        void reached(std::int64_t position);

        std::string mPath;
        ProgressCallback mProgress;
        std::string mMessage;
        std::ifstream mFile;
        std::vector<char> mBytes;
        std::int64_t mBytesStart = 0; // the file offset of mBytes[0]
        std::int64_t mBegin = 0;
        std::int64_t mEnd = 0;
        std::int64_t mNextReport = 0;
    };

    Buffer mBuffer;
};

} // namespace texsplat::volume::detail
