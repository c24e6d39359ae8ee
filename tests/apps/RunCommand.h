#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
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

/// @brief Runs `<launcher> texsplat <arguments>` through the shell (arguments are passed as
/// written; `launcher`, e.g. "xvfb-run -a", may be empty) and captures stdout and stderr
/// separately. ctest runs tests in parallel processes, so the file
/// that catches stderr is named after this process.
inline CommandOutput runTexsplat(const std::string& arguments,
                                 const std::string& launcher = "") {
    const std::string errorFile =
        ::testing::TempDir() + "texsplat_stderr_" + std::to_string(getpid()) + ".txt";
    const std::string command =
        launcher + " " + TEXSPLAT_EXECUTABLE + " " + arguments + " 2>" + errorFile;
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

/// @brief A test with a scratch directory of its own, named after the process and the test
/// (ctest runs tests in parallel processes), removed when the test ends.
class ScratchDirectoryTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDirectory = std::filesystem::path(::testing::TempDir()) /
                     ("texsplat_" + std::string(info->test_suite_name()) + "_" +
                      std::to_string(getpid()) + "_" + info->name());
        std::filesystem::remove_all(mDirectory);
        std::filesystem::create_directories(mDirectory);
    }
    void TearDown() override {
        if (!mDirectory.empty())
            std::filesystem::remove_all(mDirectory);
    }

    /// @brief The path of `name` in the scratch directory.
    std::string path(const std::string& name) const { return (mDirectory / name).string(); }

    /// @brief Writes `text` to `name` in the scratch directory and returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        const std::string file = path(name);
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    /// @brief The whole content of `file` (empty when it cannot be read).
    static std::string read(const std::string& file) {
        std::ifstream stream(file, std::ios::binary);
        std::ostringstream text;
        text << stream.rdbuf();
        return text.str();
    }

private:
    std::filesystem::path mDirectory;
};

} // namespace texsplat::test
