// Every output a command writes is checked before any work (issue 14): the folder exists, is a
// folder and is writable, the name is not a folder, the extension is known. Each command is given
// an input that would fail later (a missing scene or image), so the output's error proves the
// order.

#include "RunCommand.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using texsplat::test::runTexsplat;

namespace {

class OutputPathTest : public texsplat::test::ScratchDirectoryTest {};

} // namespace

TEST_F(OutputPathTest, renderChecksItsImageBeforeReadingTheScene) {
    const std::string missing = path("missing.iv");
    const std::string image = path("no-such-folder/out.png");
    const auto output = runTexsplat("render " + missing + " -o " + image);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: " + image + ": cannot write the image: " +
                                        "folder '" + path("no-such-folder") +
                                        "' does not exist\n");

    const auto folder = runTexsplat("render " + missing + " -o " + path(""));
    EXPECT_EQ(folder.standardError,
              "texsplat: error: " + path("") + ": no image extension (supported: .png, .exr)\n");
    fs::create_directory(path("folder.png"));
    const auto named = runTexsplat("render " + missing + " -o " + path("folder.png"));
    EXPECT_EQ(named.standardError, "texsplat: error: " + path("folder.png") +
                                       ": cannot write the image: it is a folder\n");
    write("file", "");
    const auto underFile = runTexsplat("render " + missing + " -o " + path("file/out.png"));
    EXPECT_EQ(underFile.standardError, "texsplat: error: " + path("file/out.png") +
                                           ": cannot write the image: '" + path("file") +
                                           "' is not a folder\n");
}

TEST_F(OutputPathTest, benchChecksItsCsvAndPlotBeforeTheRun) {
    const std::string csv = path("gone/bench.csv");
    const auto output =
        runTexsplat("bench --dataset ml8 --size 32x24 --repeat 1 --backend cpu --csv " + csv);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardOutput, "");
    EXPECT_EQ(output.standardError, "texsplat: error: " + csv + ": cannot write the CSV file: " +
                                        "folder '" + path("gone") + "' does not exist\n");

    const auto extension = runTexsplat(
        "bench --dataset ml8 --size 32x24 --repeat 1 --backend cpu --csv " + path("bench.txt"));
    EXPECT_EQ(extension.standardError, "texsplat: error: " + path("bench.txt") +
                                           ": unknown CSV extension '.txt' (supported: .csv)\n");

    const std::string plot = path("gone/bench.svg");
    const auto plotOutput =
        runTexsplat("bench --dataset ml8 --size 32x24 --repeat 1 --backend cpu --plot " + plot);
    EXPECT_EQ(plotOutput.standardOutput, "");
    EXPECT_EQ(plotOutput.standardError, "texsplat: error: " + plot + ": cannot write the plot: " +
                                            "folder '" + path("gone") + "' does not exist\n");
}

TEST_F(OutputPathTest, compareChecksItsDifferenceImageBeforeReadingTheImages) {
    const std::string missing = path("missing.png");
    const std::string diff = path("gone/diff.png");
    const auto output = runTexsplat("compare " + missing + " " + missing + " --diff " + diff);
    EXPECT_EQ(output.exitCode, 1);
    EXPECT_EQ(output.standardError, "texsplat: error: " + diff +
                                        ": cannot write the difference image: folder '" +
                                        path("gone") + "' does not exist\n");

    const auto extension =
        runTexsplat("compare " + missing + " " + missing + " --diff " + path("diff.jpg"));
    EXPECT_EQ(extension.standardError,
              "texsplat: error: " + path("diff.jpg") +
                  ": unknown image extension '.jpg' (supported: .png, .exr)\n");
}
