#include "nodes/volume/Progress.h"

namespace texsplat::volume {

void reportProgress(const ProgressCallback& progress, const std::string& source, double fraction,
                    std::string_view message) {
    if (progress && !progress(fraction, message))
        throw LoadCancelled(source + ": loading cancelled");
}

} // namespace texsplat::volume
