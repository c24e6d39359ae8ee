#pragma once

#include "scenegraph/Error.h"

#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>

namespace texsplat {

/// @brief The resource guard: the most memory (bytes) one piece of large work may ask for (a
/// grid, its classification, an octree, a splat list, an image), asked before allocating.
///
/// The limit is the last setMemoryLimit(), else the machine's physical memory (0 when the
/// system does not say: then nothing is refused). The `texsplat` commands set it from
/// `--memory-limit`, whose default is the memory available when they start.
std::uint64_t memoryLimit();

/// @brief Sets the limit and returns the previous setting; 0 restores the default (physical
/// memory). Thread-safe.
std::uint64_t setMemoryLimit(std::uint64_t bytes);

/// @brief The memory the system could give this process now without swapping (Linux'
/// MemAvailable), else its physical memory; 0 when the system says neither.
std::uint64_t availableMemoryBytes();

/// @brief "12884901888 bytes (12 GiB)", "26214400 bytes (25 MiB)": a byte count as people
/// read it (the rounded size in KiB at least).
std::string bytesText(std::uint64_t bytes);

/// @brief A byte count as people write it: a whole or decimal number with an optional suffix
/// K, M, G or T (powers of 1024, case-insensitive, an optional trailing 'B' or 'iB'), e.g.
/// "512M", "1.5G", "1000000".
/// @throws DataError "expected a byte count such as 512M or 8G, got '<text>'" otherwise, and for
/// zero or a count beyond 2^64.
std::uint64_t parseByteCount(std::string_view text);

/// @brief Refuses work before it allocates: throws ResourceError "<what> would need <bytes>, more
/// than the memory limit of <limit>; <advice>" when `bytes` exceeds memoryLimit().
void checkMemory(std::string_view what, std::uint64_t bytes, std::string_view advice);

/// @brief `count` × `each` bytes, saturating at the largest std::uint64_t instead of wrapping
/// (a grid of 2^60 voxels must not wrap to a few bytes and pass the check; any limit refuses the
/// saturated value).
std::uint64_t byteProduct(std::uint64_t count, std::uint64_t each);

/// @brief `a` + `b` bytes, saturating like byteProduct().
std::uint64_t byteSum(std::uint64_t a, std::uint64_t b);

/// @brief The message of a std::bad_alloc caught in `stage`: "<stage>: out of memory (...)",
/// with the stage's estimate when known (`estimate` > 0), the limit and `advice`.
std::string outOfMemoryText(std::string_view stage, std::uint64_t estimate,
                            std::string_view advice);

/// @brief Runs `step`, one stage of large work ("classifying 64x64x64 voxels"); a std::bad_alloc
/// it throws (or std::length_error: a container asked for more than it can address) becomes a
/// ResourceError saying which stage ran out, its estimate (`estimate` bytes,
/// 0 when unknown) and `advice` (what to do), so that running out of memory is reported like
/// any other expected failure. Only the first (innermost) stage names itself: a ResourceError
/// passes through enclosing stages unchanged.
template <class Step>
auto withMemoryStage(std::string_view stage, std::uint64_t estimate, std::string_view advice,
                     Step&& step) {
    try {
        return step();
    } catch (const std::bad_alloc&) {
        throw ResourceError(outOfMemoryText(stage, estimate, advice));
    } catch (const std::length_error&) {
        throw ResourceError(outOfMemoryText(stage, estimate, advice));
    }
}

} // namespace texsplat
