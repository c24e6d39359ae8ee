#pragma once

// Helpers for the tests that check a reader on files written by another program (teem's unu,
// NetCDF's ncgen): they find the program and run it.

#include <cstdlib>
#include <initializer_list>
#include <string>

namespace texsplat::nodes::test {

/// The first of `names` that the shell finds on PATH, or "" when none is installed.
inline std::string findTool(std::initializer_list<const char*> names) {
    for (const char* name : names) {
        const std::string check = std::string("command -v ") + name + " >/dev/null 2>&1";
        if (std::system(check.c_str()) == 0)
            return name;
    }
    return {};
}

/// Runs the shell command `command`; whether it succeeded.
inline bool runTool(const std::string& command) { return std::system(command.c_str()) == 0; }

/// `text` quoted for the shell.
inline std::string shellQuoted(const std::string& text) {
    std::string quoted = "'";
    for (const char c : text)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

} // namespace texsplat::nodes::test
