#pragma once

// The process's memory limit set for one test and restored after it.

#include "scenegraph/MemoryLimit.h"

#include <cstdint>

namespace texsplat::test {

/// Sets texsplat::setMemoryLimit(`bytes`) for its lifetime.
class ScopedMemoryLimit {
public:
    explicit ScopedMemoryLimit(std::uint64_t bytes) : mPrevious(setMemoryLimit(bytes)) {}
    ~ScopedMemoryLimit() { setMemoryLimit(mPrevious); }
    ScopedMemoryLimit(const ScopedMemoryLimit&) = delete;
    ScopedMemoryLimit& operator=(const ScopedMemoryLimit&) = delete;

private:
    std::uint64_t mPrevious;
};

} // namespace texsplat::test
