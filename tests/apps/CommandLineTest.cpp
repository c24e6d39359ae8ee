#include "RunCommand.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using texsplat::test::runTexsplat;

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

} // namespace
