#pragma once

#include <functional>
#include <memory>
#include <string>

namespace texsplat::nodes::detail {

/// @brief What loading a file yields, shared by every node that loads the same thing while
/// one of them holds it: two VolumeData nodes naming one file read it once and hold one grid,
/// and the grid goes when the last holder lets it go (the cache keeps only weak references).
///
/// `key` names what is loaded completely: the file's canonical path, its size and modification
/// time (a changed file is read again), and every field that shapes the result. Two threads that
/// load the same key at once may both read it; each gets a complete result.
std::shared_ptr<const void> sharedLoad(const std::string& key,
                                       const std::function<std::shared_ptr<const void>()>& load);

/// @brief sharedLoad() for a result of type T.
template <class T>
std::shared_ptr<const T> sharedLoad(const std::string& key,
                                    const std::function<std::shared_ptr<const T>()>& load) {
    return std::static_pointer_cast<const T>(
        sharedLoad(key, std::function<std::shared_ptr<const void>()>(
                            [&load]() -> std::shared_ptr<const void> { return load(); })));
}

/// @brief The key part that names a file as it is now: canonical path, size and modification
/// time, or the path as given when the file cannot be inspected (its loader then reports why).
std::string fileIdentity(const std::string& path);

} // namespace texsplat::nodes::detail
