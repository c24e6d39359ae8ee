#include "scenegraph/Assert.h"

#include <cstdio>
#include <cstdlib>

namespace texsplat::detail {

void assertionFailed(const char* condition, const char* message, const char* file,
                     int line) noexcept {
    std::fprintf(stderr, "%s:%d: texsplat assertion failed: %s (%s)\n", file, line, message,
                 condition);
    std::abort();
}

} // namespace texsplat::detail
