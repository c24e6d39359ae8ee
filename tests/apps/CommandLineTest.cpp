#include "RunCommand.h"

#include "apps/CommandLine.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

using texsplat::test::runTexsplat;

// What runCommandLine answers and prints for `arguments` (after "texsplat") in `mode`.
struct CheckedCommandLine {
    int exitCode;
    std::string out;
    std::string errors;
};

CheckedCommandLine runInProcess(const std::vector<std::string>& arguments,
                                texsplat::apps::CommandMode mode) {
    std::vector<const char*> argv{"texsplat"};
    for (const std::string& argument : arguments)
        argv.push_back(argument.c_str());
    std::ostringstream out;
    std::ostringstream errors;
    const int exitCode =
        texsplat::apps::runCommandLine(int(argv.size()), argv.data(), mode, out, errors);
    return {exitCode, out.str(), errors.str()};
}

TEST(CommandLine, versionSaysWhatThisBuildCanDo) {
    const auto output = runTexsplat("--version");
    EXPECT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_EQ(output.standardOutput.rfind("texsplat 0.", 0), 0u) << output.standardOutput;
    EXPECT_NE(output.standardOutput.find("\nbackends: CPU ("), std::string::npos)
        << output.standardOutput;
    EXPECT_NE(output.standardOutput.find("OpenVDB: "), std::string::npos) << output.standardOutput;
}

TEST(CommandLine, usageErrorsComeInTheSameFormAsEveryErrorWithTheUsageCode) {
    auto output = runTexsplat("");
    EXPECT_EQ(output.exitCode, 2);
    EXPECT_EQ(output.standardError,
              "texsplat: error: A subcommand is required\nRun with --help for more information.\n");
    output = runTexsplat("render -o x.png --frobnicate");
    EXPECT_EQ(output.exitCode, 2);
    EXPECT_EQ(output.standardError.rfind("texsplat: error: ", 0), 0u) << output.standardError;
    EXPECT_NE(output.standardError.find("--frobnicate"), std::string::npos)
        << output.standardError;
    output = runTexsplat("--help");
    EXPECT_EQ(output.exitCode, 0);
    EXPECT_NE(output.standardOutput.find("render"), std::string::npos);
}

TEST(CommandLine, checkingOptionsRefusesWhatRunningWouldRefuseAndDoesNoWork) {
    using texsplat::apps::CommandMode;
    const std::string output =
        (std::filesystem::path(::testing::TempDir()) / "CommandLineTest_checked.png").string();
    std::filesystem::remove(output);
    // Valid options of a scene that does not exist: nothing is read, written or rendered.
    auto checked = runInProcess({"render", "no-such-scene.iv", "-o", output, "--size", "64x32"},
                                CommandMode::CheckOptions);
    EXPECT_EQ(checked.exitCode, 0) << checked.errors;
    EXPECT_EQ(checked.errors, "");
    EXPECT_FALSE(std::filesystem::exists(output));
    // The same scene run: reading it fails.
    checked = runInProcess({"render", "no-such-scene.iv", "-o", output}, CommandMode::Run);
    EXPECT_EQ(checked.exitCode, 1);
    EXPECT_NE(checked.errors.find("no-such-scene.iv"), std::string::npos) << checked.errors;
    // Option values are checked as a run checks them, before any work.
    for (const CommandMode mode : {CommandMode::CheckOptions, CommandMode::Run}) {
        checked = runInProcess({"render", "no-such-scene.iv", "-o", output, "--size", "64"}, mode);
        EXPECT_EQ(checked.exitCode, 1);
        EXPECT_EQ(checked.errors,
                  "texsplat: error: --size: expected WxH with whole numbers from 1 to 16384, "
                  "got '64'\n");
        checked = runInProcess({"compare", "a.png", "b.png", "--memory-limit", "lots"}, mode);
        EXPECT_EQ(checked.errors, "texsplat: error: --memory-limit: expected a byte count such "
                                  "as 512M or 8G, got 'lots'\n");
    }
}

} // namespace
