#pragma once

#include <cstdint>
#include <string>

namespace CLI {
class App;
} // namespace CLI

namespace texsplat::apps {

/// @brief Adds `--memory-limit BYTES` (512M, 8G, …) to `command`, filling `value`: the most
/// memory that one piece of large work may ask for (texsplat::memoryLimit()).
void addMemoryLimitOption(CLI::App& command, std::string& value);

/// @brief The memory limit the option's `value` asks for; empty: the memory available now.
/// Throws DataError naming --memory-limit for a value that is not a byte count.
std::uint64_t memoryLimitOf(const std::string& value);

} // namespace texsplat::apps
