#pragma once

#include <string>

namespace CLI {
class App;
} // namespace CLI

namespace texsplat::apps {

/// @brief Adds `--memory-limit BYTES` (512M, 8G, …) to `command`, filling `value`: the most
/// memory that one piece of large work may ask for (texsplat::memoryLimit()).
void addMemoryLimitOption(CLI::App& command, std::string& value);

/// @brief Sets the process's memory limit from the option's `value`; empty: the memory
/// available now. Throws DataError naming --memory-limit for a value that is not a byte count.
void applyMemoryLimit(const std::string& value);

} // namespace texsplat::apps
