#pragma once

#include "scenegraph/Error.h"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace texsplat::volume {

/// @brief Called by loaders now and then with the fraction done (0 to 1) and what they are
/// doing. Return false to cancel: the loader then throws LoadCancelled.
using ProgressCallback = std::function<bool(double fraction, std::string_view message)>;

/// @brief Thrown when a ProgressCallback asked a loader to stop; the message names the file.
class LoadCancelled : public Error {
public:
    using Error::Error;
};

/// @brief Reports progress to `progress` (when set) and throws LoadCancelled("<source>: loading
/// cancelled") when it answers false.
void reportProgress(const ProgressCallback& progress, const std::string& source, double fraction,
                    std::string_view message);

/// @brief From this file size on, logProgress() logs from the first report. Reading and decoding
/// 64 MiB takes from a few tenths of a second (from the page cache) to seconds (a slow or network
/// disk): long enough for a silent program to look stuck. Smaller files load too fast for
/// progress lines to help; they would only clutter batch logs.
inline constexpr std::int64_t kLogProgressFileBytes = std::int64_t{64} << 20;

/// @brief After this many seconds of loading, logProgress() logs whatever the file size: a small
/// file may still load slowly (an OpenVDB file whose active tiles expand into many voxels).
inline constexpr double kLogProgressDelaySeconds = 1.0;

/// @brief A ProgressCallback that tells the user how a load goes, through texsplat::log at
/// LogLevel::Info: "<source>: <message>" when the loader starts a step (a new message), then
/// "<source>: <message> <percent>%" each time the load passes a further 10 %.
///
/// For a file of `fileBytes` >= kLogProgressFileBytes it logs from the first report; for a
/// smaller one only once the load has run kLogProgressDelaySeconds (counted from this call), so
/// quick loads stay quiet. It never cancels.
ProgressCallback logProgress(std::string source, std::int64_t fileBytes);

} // namespace texsplat::volume
