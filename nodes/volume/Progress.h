#pragma once

#include "scenegraph/Error.h"

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

} // namespace texsplat::volume
