#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace texsplat {

/// @brief Severity of a log message.
enum class LogLevel { Debug, Info, Warning, Error };

/// @brief Receives every message the library logs. Applications print them; tests capture them.
using LogSink = std::function<void(LogLevel level, std::string_view message)>;

/// @brief Replaces the sink and returns the previous one. The default sink drops Debug and
/// writes the rest to standard error; pass an empty function to silence the library.
LogSink setLogSink(LogSink sink);

/// @brief Sends one message to the current sink. Thread-safe.
void log(LogLevel level, std::string_view message);

/// @brief Short, lower-case name of a level ("warning").
std::string_view toString(LogLevel level);

} // namespace texsplat
