#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace texsplat::test {

/// @brief What one run of the texsplat executable printed and returned.
struct CommandOutput {
    int exitCode = -1;
    std::string standardOutput;
    std::string standardError;
};

/// @brief Runs `texsplat <arguments>` through the shell (arguments are passed as written) and
/// captures stdout and stderr separately. ctest runs tests in parallel processes, so the file
/// that catches stderr is named after this process.
inline CommandOutput runTexsplat(const std::string& arguments) {
    const std::string errorFile =
        ::testing::TempDir() + "texsplat_stderr_" + std::to_string(getpid()) + ".txt";
    const std::string command =
        std::string(TEXSPLAT_EXECUTABLE) + " " + arguments + " 2>" + errorFile;
    CommandOutput output;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe)
        return output;
    std::array<char, 4096> buffer{};
    size_t count = 0;
    while ((count = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        output.standardOutput.append(buffer.data(), count);
    const int status = pclose(pipe);
    output.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (FILE* errors = fopen(errorFile.c_str(), "r")) {
        while ((count = fread(buffer.data(), 1, buffer.size(), errors)) > 0)
            output.standardError.append(buffer.data(), count);
        fclose(errors);
    }
    std::remove(errorFile.c_str());
    return output;
}

} // namespace texsplat::test
