#include "RunCommand.h"

#include "nodes/image/Image.h"
#include "nodes/image/ImageIo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using texsplat::test::runTexsplat;

namespace {

// Data files in place of scenes (`texsplat render DATA -o x.png`), and `--data-root`, which
// confines the files a scene reads (issue 31).
class DataFileCommandTest : public texsplat::test::ScratchDirectoryTest {
protected:
    // A 16³ ball of bytes, brighter at its centre, as headerless raw values.
    static std::string ballBytes() {
        std::string bytes;
        for (int z = 0; z < 16; ++z)
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) {
                    const double r = std::hypot(x - 7.5, y - 7.5, z - 7.5);
                    bytes += static_cast<char>(r < 7.0 ? 200 - static_cast<int>(25.0 * r) : 0);
                }
        return bytes;
    }

    // The largest colour channel of any pixel of the PNG at `file`.
    static float brightest(const std::string& file) {
        const texsplat::image::Image image = texsplat::image::readImage(file);
        float most = 0.0f;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const glm::vec4 pixel = image.pixel(x, y);
                most = std::max({most, pixel.r, pixel.g, pixel.b});
            }
        return most;
    }
};

TEST_F(DataFileCommandTest, rendersADataFileWithTheSceneInfoPrints) {
    const std::string data =
        write("ball.raw", "texsplat-raw 1\ndims 16 16 16\ntype uint8\ndata\n" + ballBytes());
    const auto output =
        runTexsplat("render " + data + " --size 48x48 --backend cpu -o " + path("ball.png"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_EQ(output.standardError,
              "texsplat: " + data + " is a data file: drawing it with the scene `texsplat info " +
                  data + " --scene` prints; to edit it, save it (texsplat info " + data +
                  " --scene > scene.iv) and render scene.iv\n");
    EXPECT_GT(brightest(path("ball.png")), 0.1f);
    // The scene saved and rendered gives the same picture.
    const auto scene = runTexsplat("info " + data + " --scene");
    write("ball.iv", scene.standardOutput);
    ASSERT_EQ(runTexsplat("render " + path("ball.iv") + " --size 48x48 --backend cpu -o " +
                          path("saved.png"))
                  .exitCode,
              0);
    EXPECT_EQ(read(path("saved.png")), read(path("ball.png")));
}

TEST_F(DataFileCommandTest, rendersAHeaderlessRawFileWithItsLayoutGiven) {
    const std::string data = write("ct.raw", ballBytes());
    const auto output = runTexsplat("render " + data + " --dims 16,16,16 --type uint8 --size "
                                    "32x32 --backend cpu -o " + path("ct.png"));
    ASSERT_EQ(output.exitCode, 0) << output.standardError;
    EXPECT_NE(output.standardError.find("`texsplat info " + data +
                                        " --dims 16,16,16 --type uint8 --scene`"),
              std::string::npos)
        << output.standardError;
    EXPECT_GT(brightest(path("ct.png")), 0.1f);
    const auto mistaken =
        runTexsplat("render --dims 16,16,16 --type uint8 -o " + path("ct.png"));
    EXPECT_EQ(mistaken.standardError, "texsplat: error: --dims: names the layout of a headerless "
                                      "raw file given as the scene\n");
}

// A service that renders scenes it did not write: with --data-root, a scene reads only files
// inside it, whatever path it gives (`..`, absolute, through a link), and a NRRD header's data
// file is held to the same folders.
TEST_F(DataFileCommandTest, dataRootConfinesEveryFileASceneReads) {
    fs::create_directories(path("root/scenes"));
    const std::string secret =
        write("secret.raw", "texsplat-raw 1\ndims 2 2 2\ntype uint8\ndata\n" +
                                std::string(8, '\x01'));
    write("root/ball.raw",
          "texsplat-raw 1\ndims 16 16 16\ntype uint8\ndata\n" + ballBytes());
    const auto scene = [&](const std::string& name, const std::string& fileName) {
        return write("root/scenes/" + name,
                     "#Inventor V2.1 ascii\nSeparator {\nTransferFunction { preset HOT }\n"
                     "VolumeData { source FILE_RAW fileName \"" + fileName +
                         "\" }\nTextureSplat { }\n}\n");
    };
    const std::string root = fs::canonical(path("root")).string();
    const std::string inside = scene("inside.iv", "../ball.raw");
    const auto good = runTexsplat("render " + inside + " --data-root " + root +
                                  " --size 16x16 --backend cpu -o " + path("good.png"));
    EXPECT_EQ(good.exitCode, 0) << good.standardError;

    const std::string outside = scene("outside.iv", "../../secret.raw");
    const auto refused = runTexsplat("render " + outside + " --data-root " + root +
                                     " --size 16x16 -o " + path("bad.png"));
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_EQ(refused.standardError,
              "texsplat: error: " + outside + ":4:1: VolumeData: " + path("root/scenes") +
                  "/../../secret.raw: cannot read file: it lies outside the data roots (" + root +
                  ") (it leads to " + fs::canonical(secret).string() +
                  "), which --data-root confines the files a scene reads to\n");
    EXPECT_FALSE(fs::exists(path("bad.png")));
    // Without it, the scene's files are its author's business, as before.
    EXPECT_EQ(runTexsplat("render " + outside + " --size 16x16 -o " + path("bad.png")).exitCode,
              0);

    // A detached NRRD header inside the root whose data file is outside.
    const std::string header = write("root/data.nhdr", "NRRD0004\ntype: uint8\ndimension: 3\n"
                                                       "sizes: 2 2 2\nencoding: raw\n"
                                                       "data file: ../secret.raw\n");
    const auto info = runTexsplat("info " + header + " --data-root " + root);
    EXPECT_EQ(info.exitCode, 1);
    EXPECT_EQ(info.standardError,
              "texsplat: error: " + path("secret.raw") +
                  ": cannot read the NRRD header's data file: it lies outside the data roots (" +
                  root + "), which --data-root confines the files a scene reads to\n");
    EXPECT_EQ(runTexsplat("info " + path("secret.raw") + " --data-root " + root).standardError,
              "texsplat: error: " + path("secret.raw") +
                  ": cannot read data file: it lies outside the data roots (" + root +
                  "), which --data-root confines the files a scene reads to\n");
    EXPECT_EQ(runTexsplat("render " + inside + " --data-root " + path("none") + " -o " +
                          path("x.png"))
                  .standardError,
              "texsplat: error: --data-root: " + path("none") +
                  ": cannot use as a data root: No such file or directory\n");
}

} // namespace
