#include "scenegraph/WorkProgress.h"

#include <string>

namespace texsplat::sg {

void reportWork(const WorkProgress& progress, std::string_view step, double fraction) {
    if (progress && !progress(step, fraction)) {
        throw Cancelled(std::string(step) + ": cancelled");
    }
}

} // namespace texsplat::sg
