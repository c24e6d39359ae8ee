#include "scenegraph/io/DataRoots.h"

#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace texsplat::sg {
namespace {

namespace fs = std::filesystem;

class DataRootsTest : public ::testing::Test {
protected:
    void SetUp() override {
        mFolder = fs::path(::testing::TempDir()) /
                  ("DataRootsTest_" + std::to_string(getpid()) + "_" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(mFolder);
        fs::create_directories(mFolder / "data" / "clouds");
        fs::create_directories(mFolder / "private");
        std::ofstream(mFolder / "data" / "clouds" / "cloud.npy") << "cloud";
        std::ofstream(mFolder / "private" / "secret.raw") << "secret";
        // The real path of the scratch folder (TempDir may itself lie behind a link).
        mFolder = fs::canonical(mFolder);
    }
    void TearDown() override { fs::remove_all(mFolder); }

    std::string path(const std::string& name) const { return (mFolder / name).string(); }

    // The message of the IoError that check() throws for `file`; empty when it passes.
    static std::string refusal(const DataRoots& roots, const std::string& file) {
        try {
            roots.check(file, "file");
        } catch (const IoError& error) {
            return error.what();
        }
        return {};
    }

    fs::path mFolder;
};

TEST_F(DataRootsTest, withoutRootsEveryFileMayBeRead) {
    const DataRoots roots;
    EXPECT_FALSE(roots.isConfined());
    EXPECT_EQ(refusal(roots, "/etc/passwd"), "");
}

TEST_F(DataRootsTest, filesInsideARootAreReadAndOthersRefusedBeforeOpening) {
    const DataRoots roots({path("data")});
    EXPECT_TRUE(roots.isConfined());
    EXPECT_EQ(refusal(roots, path("data/clouds/cloud.npy")), "");
    // Not there yet: judged by its folder, so that opening it says what is missing.
    EXPECT_EQ(refusal(roots, path("data/clouds/later.npy")), "");
    EXPECT_EQ(refusal(roots, "/etc/passwd"),
              "/etc/passwd: cannot read file: it lies outside the data roots (" + path("data") +
                  "), which --data-root confines the files a scene reads to");
    // A folder whose name starts like the root's is not inside it.
    fs::create_directories(mFolder / "database");
    EXPECT_NE(refusal(roots, path("database/x.npy")), "");
}

TEST_F(DataRootsTest, dotDotAndSymbolicLinksAreResolvedFirst) {
    const DataRoots roots({path("data")});
    // A scene's `fileName "../../etc/passwd"` relative to its folder.
    const std::string climbing = path("data/clouds/../../private/secret.raw");
    EXPECT_EQ(refusal(roots, climbing),
              climbing + ": cannot read file: it lies outside the data roots (" + path("data") +
                  ") (it leads to " + path("private/secret.raw") +
                  "), which --data-root confines the files a scene reads to");
    fs::create_symlink(path("private/secret.raw"), path("data/link.raw"));
    EXPECT_EQ(refusal(roots, path("data/link.raw")),
              path("data/link.raw") + ": cannot read file: it lies outside the data roots (" +
                  path("data") + ") (it leads to " + path("private/secret.raw") +
                  "), which --data-root confines the files a scene reads to");
    // A link that stays inside is followed.
    fs::create_symlink(path("data/clouds/cloud.npy"), path("data/inside.npy"));
    EXPECT_EQ(refusal(roots, path("data/inside.npy")), "");
    // A root given through a link is the folder it leads to.
    fs::create_directory_symlink(path("data"), path("alias"));
    EXPECT_EQ(refusal(DataRoots({path("alias")}), path("data/clouds/cloud.npy")), "");
}

TEST_F(DataRootsTest, severalRootsAndRootsThatAreNotFolders) {
    const DataRoots roots({path("data"), path("private")});
    EXPECT_EQ(refusal(roots, path("private/secret.raw")), "");
    EXPECT_EQ(roots.folders().size(), 2u);
    try {
        DataRoots({path("missing")});
        FAIL() << "no error";
    } catch (const IoError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path("missing") + ": cannot use as a data root: No such file or directory");
    }
    try {
        DataRoots({path("private/secret.raw")});
        FAIL() << "no error";
    } catch (const IoError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path("private/secret.raw") + ": cannot use as a data root: Not a directory");
    }
}

} // namespace
} // namespace texsplat::sg
