#include "scenegraph/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <unistd.h>

namespace texsplat {
namespace {

namespace fs = std::filesystem;

std::set<std::string> namesIn(const fs::path& folder) {
    std::set<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        names.insert(entry.path().filename().string());
    return names;
}

class AtomicFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        mFolder = fs::path(::testing::TempDir()) /
                  ("AtomicFileTest_" + std::to_string(getpid()) + "_" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(mFolder);
        fs::create_directories(mFolder);
    }
    void TearDown() override { fs::remove_all(mFolder); }

    fs::path mFolder;
};

// An animation killed while it wrote a frame left the frame's ".tmp" file behind: while the
// contents are written, the folder holds no file of them, so a kill at that moment leaves none.
TEST_F(AtomicFileTest, whileTheContentsAreWrittenTheFolderHoldsNoFileOfThem) {
    const std::string target = (mFolder / "frame0001.png").string();
    std::ofstream(mFolder / "other.txt") << "kept";
    std::set<std::string> duringWrite;
    writeFileAtomically(target, [&](std::ofstream& stream) {
        stream << "first half";
        stream.flush();
        duringWrite = namesIn(mFolder);
        stream << ", second half";
    });
    EXPECT_EQ(duringWrite, std::set<std::string>{"other.txt"});
    EXPECT_EQ(namesIn(mFolder), (std::set<std::string>{"frame0001.png", "other.txt"}));
    std::ifstream written(target);
    std::ostringstream contents;
    contents << written.rdbuf();
    EXPECT_EQ(contents.str(), "first half, second half");
}

} // namespace
} // namespace texsplat
