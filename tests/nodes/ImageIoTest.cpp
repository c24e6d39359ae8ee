#include "nodes/image/ImageIo.h"

#include "scenegraph/AtomicFile.h"
#include "scenegraph/Error.h"
#include "tests/scenegraph/TestFifo.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <cstdint>
#include <limits>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using texsplat::IoError;
using texsplat::image::Image;
using texsplat::image::ImageFormat;
using texsplat::image::imageFormatOf;
using texsplat::image::readImage;
using texsplat::image::writeImage;

namespace {

/// A fresh, empty directory per test, removed afterwards.
class ImageIoTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDirectory = fs::path(::testing::TempDir()) /
                     ("texsplat_image_io_" + std::to_string(getpid()) + "_" + info->name());
        fs::remove_all(mDirectory);
        fs::create_directories(mDirectory);
    }
    void TearDown() override {
        fs::permissions(mDirectory, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(mDirectory);
    }
    std::string path(const std::string& name) const { return (mDirectory / name).string(); }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(mDirectory))
            names.push_back(entry.path().filename().string());
        return names;
    }

    fs::path mDirectory;
};

template <typename Function>
std::string ioErrorMessage(Function&& function) {
    try {
        function();
    } catch (const IoError& e) {
        return e.what();
    }
    return "no IoError";
}

/// A 5x3 image with values a PNG cannot hold: above 1, negative, tiny, and a gradient.
Image highDynamicRangeImage() {
    Image image(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            image.setPixel(x, y, {0.1f * x + 0.013f * y, 1.0f / (1 + x + y), 0.5f, 0.25f * y});
    image.setPixel(0, 0, {12345.678f, -3.25f, 1e-30f, 1.0f});
    image.setPixel(4, 2, {std::numeric_limits<float>::denorm_min(), 2.0f, 65504.5f, 0.999f});
    return image;
}

} // namespace

TEST(ImageIo, formatComesFromTheExtensionCaseInsensitively) {
    EXPECT_EQ(imageFormatOf("a/b.png"), ImageFormat::Png);
    EXPECT_EQ(imageFormatOf("B.PNG"), ImageFormat::Png);
    EXPECT_EQ(imageFormatOf("render.exr"), ImageFormat::Exr);
    EXPECT_EQ(ioErrorMessage([] { imageFormatOf("out.tif"); }),
              "out.tif: unknown image extension '.tif' (supported: .png, .exr)");
    EXPECT_EQ(ioErrorMessage([] { imageFormatOf("dir.png/out"); }),
              "dir.png/out: no image extension (supported: .png, .exr)");
    // `-o ""` said ": no image extension".
    EXPECT_EQ(ioErrorMessage([] { imageFormatOf(""); }),
              "the image file name is empty (supported extensions: .png, .exr)");
}

TEST_F(ImageIoTest, exrRoundTripIsExactIncludingDepth) {
    if (!texsplat::image::isExrSupported())
        GTEST_SKIP() << "built without OpenEXR";
    Image image = highDynamicRangeImage();
    image.addDepth();
    image.setDepth(1, 1, 3.75f);
    image.setDepth(2, 0, -0.0f);
    writeImage(image, path("hdr.exr"));
    const Image read = readImage(path("hdr.exr"));
    ASSERT_EQ(read.width(), 5);
    ASSERT_EQ(read.height(), 3);
    ASSERT_TRUE(read.hasDepth());
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        EXPECT_EQ(read.pixels()[i], image.pixels()[i]) << "pixel " << i;
        EXPECT_EQ(read.depths()[i], image.depths()[i]) << "depth " << i;
    }
    EXPECT_EQ(read.depth(0, 0), std::numeric_limits<float>::infinity());
    EXPECT_EQ(entries(), std::vector<std::string>{"hdr.exr"});
}

TEST_F(ImageIoTest, exrWithoutDepthReadsWithoutDepth) {
    if (!texsplat::image::isExrSupported())
        GTEST_SKIP() << "built without OpenEXR";
    writeImage(highDynamicRangeImage(), path("color.exr"));
    const Image read = readImage(path("color.exr"));
    EXPECT_FALSE(read.hasDepth());
    EXPECT_EQ(read.pixel(0, 0), glm::vec4(12345.678f, -3.25f, 1e-30f, 1.0f));
}

TEST_F(ImageIoTest, pngRoundTripIsWithinEightBitQuantization) {
    Image image(16, 4);
    for (int x = 0; x < 16; ++x) {
        const float value = x / 15.0f;
        image.setPixel(x, 0, {value, value * value, 1.0f - value, 1.0f}); // opaque
        image.setPixel(x, 1, glm::vec4(glm::vec3(0.5f * value), 0.5f));  // half transparent
        image.setPixel(x, 2, {0.0002f * x, 0.0f, 0.0f, 1.0f});            // dark
        image.setPixel(x, 3, {2.0f, -1.0f, 0.5f, 1.0f});                  // out of range
    }
    writeImage(image, path("ldr.png"));
    const Image read = readImage(path("ldr.png"));
    ASSERT_EQ(read.width(), 16);
    ASSERT_EQ(read.height(), 4);
    EXPECT_FALSE(read.hasDepth());
    // Values are stored as they are, so a round trip is off by at most half an 8-bit step
    // (1/510), plus float rounding; a translucent pixel's colour by that step times alpha.
    constexpr float kHalfStep = 0.5f / 255.0f + 1e-6f;
    for (int x = 0; x < 16; ++x) {
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(read.pixel(x, 0)[c], image.pixel(x, 0)[c], kHalfStep) << x << "," << c;
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(read.pixel(x, 1)[c], image.pixel(x, 1)[c], kHalfStep) << x << "," << c;
        EXPECT_NEAR(read.pixel(x, 2).r, image.pixel(x, 2).r, kHalfStep) << x;
        const glm::vec4 clamped(1.0f, 0.0f, 0.5f, 1.0f);
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(read.pixel(x, 3)[c], clamped[c], kHalfStep) << x << "," << c;
    }
}

TEST_F(ImageIoTest, pngBytesAreTheFileWriteImageWrites) {
    const Image image = highDynamicRangeImage();
    writeImage(image, path("image.png"));
    std::ifstream file(path("image.png"), std::ios::binary);
    const std::string written((std::istreambuf_iterator<char>(file)),
                              std::istreambuf_iterator<char>());
    EXPECT_EQ(texsplat::image::pngBytes(image), written);
    EXPECT_EQ(written.substr(1, 3), "PNG");
}

TEST_F(ImageIoTest, pngStoresNonFinitePixelsAsTransparentBlack) {
    Image image(2, 1);
    image.setPixel(0, 0, {std::nanf(""), 0.5f, 0.5f, 1.0f});
    image.setPixel(1, 0, {0.5f, 0.5f, 0.5f, std::numeric_limits<float>::infinity()});
    writeImage(image, path("nan.png"));
    const Image read = readImage(path("nan.png"));
    EXPECT_EQ(read.pixel(0, 0), glm::vec4(0.0f));
    EXPECT_EQ(read.pixel(1, 0), glm::vec4(0.0f));
}

TEST_F(ImageIoTest, pngWithAnEmptyImageDataChunkFirstIsRead) {
    // Found by fuzz_png_reader: stb_image copies an empty first IDAT chunk with memcpy from a
    // null buffer (undefined behaviour, which UBSan stops at; harmless in practice). stb's code
    // is compiled without that one check (nodes/image/CMakeLists.txt); the file reads.
    Image image(3, 2);
    image.setPixel(1, 1, {1.0f, 1.0f, 1.0f, 1.0f});
    writeImage(image, path("plain.png"));
    std::ifstream in(path("plain.png"), std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::size_t data = bytes.find("IDAT");
    ASSERT_NE(data, std::string::npos);
    // Length 0, "IDAT", its CRC-32, before the chunk (its 4-byte length) that holds the pixels.
    bytes.insert(data - 4, std::string("\0\0\0\0IDAT\x35\xaf\x06\x1e", 12));
    std::ofstream(path("empty-idat.png"), std::ios::binary) << bytes;
    const Image read = readImage(path("empty-idat.png"));
    ASSERT_EQ(read.width(), 3);
    ASSERT_EQ(read.height(), 2);
    EXPECT_EQ(read.pixel(1, 1), glm::vec4(1.0f));
    EXPECT_EQ(read.pixel(0, 0), glm::vec4(0.0f));
}

TEST_F(ImageIoTest, writeReplacesAnExistingFileWhole) {
    writeImage(Image(2, 2), path("out.png"));
    writeImage(Image(7, 3), path("out.png"));
    EXPECT_EQ(readImage(path("out.png")).width(), 7);
    EXPECT_EQ(entries(), std::vector<std::string>{"out.png"});
}

TEST_F(ImageIoTest, exrInABuildWithoutOpenExrIsAClearError) {
    if (texsplat::image::isExrSupported())
        GTEST_SKIP() << "built with OpenEXR";
    const std::string target = path("out.exr");
    const std::string message =
        target + ": OpenEXR support is not built in (configure with -DTEXSPLAT_WITH_EXR=ON)";
    EXPECT_EQ(ioErrorMessage([&] { writeImage(Image(1, 1), target); }), message);
    EXPECT_EQ(ioErrorMessage([&] { readImage(target); }), message);
    EXPECT_TRUE(entries().empty());
}

TEST_F(ImageIoTest, writeIntoMissingDirectoryFailsAndLeavesNothing) {
    const std::string target = path("missing/out.png");
    EXPECT_EQ(ioErrorMessage([&] { writeImage(Image(2, 2), target); }),
              target + ": cannot create a file in directory " + path("missing") +
                  ": No such file or directory");
    EXPECT_TRUE(entries().empty());
}

TEST_F(ImageIoTest, writeBelowARegularFileFails) {
    writeImage(Image(1, 1), path("file.png"));
    const std::string target = path("file.png/out.png");
    EXPECT_EQ(ioErrorMessage([&] { writeImage(Image(2, 2), target); }),
              target + ": cannot create a file in directory " + path("file.png") +
                  ": Not a directory");
    EXPECT_EQ(entries(), std::vector<std::string>{"file.png"});
}

TEST_F(ImageIoTest, writeIntoUnwritableDirectoryFails) {
    if (geteuid() == 0)
        GTEST_SKIP() << "root may write into any directory";
    fs::create_directory(path("readonly"));
    fs::permissions(path("readonly"), fs::perms::owner_read | fs::perms::owner_exec);
    const std::string target = path("readonly/out.png");
    EXPECT_EQ(ioErrorMessage([&] { writeImage(Image(2, 2), target); }),
              target + ": cannot create a file in directory " + path("readonly") +
                  ": Permission denied");
    fs::permissions(path("readonly"), fs::perms::owner_all);
    EXPECT_TRUE(fs::is_empty(path("readonly")));
}

TEST_F(ImageIoTest, failedWriteKeepsTheOldFileAndRemovesTheTemporary) {
    const std::string target = path("kept.png");
    writeImage(Image(3, 3), target);
    EXPECT_EQ(ioErrorMessage([&] {
                  texsplat::writeFileAtomically(target, [](std::ofstream& stream) {
                      stream << "partial";
                      throw IoError("interrupted");
                  });
              }),
              "interrupted");
    EXPECT_EQ(entries(), std::vector<std::string>{"kept.png"});
    EXPECT_EQ(readImage(target).width(), 3);
}

// The rename that makes a write atomic replaced a symbolic link with a plain file.
TEST_F(ImageIoTest, writingThroughASymbolicLinkWritesItsTargetAndKeepsTheLink) {
    const std::string target = path("target.png");
    writeImage(Image(3, 3), target);
    std::filesystem::create_symlink(target, path("link.png"));
    writeImage(Image(2, 2), path("link.png"));
    EXPECT_TRUE(std::filesystem::is_symlink(path("link.png")));
    EXPECT_EQ(readImage(target).width(), 2);
    // A link to a file that does not exist yet makes that file.
    std::filesystem::create_symlink(path("later.png"), path("dangling.png"));
    writeImage(Image(4, 4), path("dangling.png"));
    EXPECT_TRUE(std::filesystem::is_symlink(path("dangling.png")));
    EXPECT_EQ(readImage(path("later.png")).width(), 4);
}

TEST_F(ImageIoTest, unknownExtensionIsRefusedBeforeWriting) {
    const std::string target = path("out.jpg");
    EXPECT_EQ(ioErrorMessage([&] { writeImage(Image(1, 1), target); }),
              target + ": unknown image extension '.jpg' (supported: .png, .exr)");
    EXPECT_TRUE(entries().empty());
}

TEST_F(ImageIoTest, readingMissingOrMalformedFilesIsIoError) {
    EXPECT_EQ(ioErrorMessage([&] { readImage(path("none.png")); }),
              path("none.png") + ": cannot open: No such file or directory");
    std::ofstream(path("text.png")) << "not a png";
    EXPECT_EQ(ioErrorMessage([&] { readImage(path("text.png")); }),
              path("text.png") + ": not a readable PNG file (unknown image type)");
    if (!texsplat::image::isExrSupported())
        return;
    EXPECT_EQ(ioErrorMessage([&] { readImage(path("none.exr")); }),
              path("none.exr") + ": cannot open: No such file or directory");
    std::ofstream(path("text.exr")) << "not an exr";
    EXPECT_EQ(ioErrorMessage([&] { readImage(path("text.exr")); })
                  .rfind(path("text.exr") + ": not a readable OpenEXR file: ", 0),
              0u);
}

// A PNG signature and an IHDR chunk declaring `width` x `height` 8-bit RGBA: all a reader sees
// before it decodes (stb does not check the CRC, left zero).
std::string pngHeader(std::uint32_t width, std::uint32_t height) {
    std::string bytes = "\x89PNG\r\n\x1a\n";
    const auto bigEndian = [&bytes](std::uint32_t value) {
        for (int shift = 24; shift >= 0; shift -= 8)
            bytes += static_cast<char>((value >> shift) & 0xff);
    };
    bigEndian(13);
    bytes += "IHDR";
    bigEndian(width);
    bigEndian(height);
    // 8 bits, RGBA, deflate, no filter, no interlace
    bytes += std::string("\x08\x06\x00\x00\x00", 5);
    bigEndian(0);
    return bytes;
}

TEST_F(ImageIoTest, aHugeImageIsRefusedFromItsHeaderBeforeDecoding) {
    // 16000 x 16000 took 9.6 GB and 31 s for `compare` of two 1 MB files.
    std::ofstream(path("huge.png"), std::ios::binary) << pngHeader(16000, 16000);
    try {
        readImage(path("huge.png"));
        FAIL() << "no error";
    } catch (const texsplat::DataError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path("huge.png") + ": the image is 16000 x 16000 pixels; texsplat reads images "
                                     "of at most 67108864 pixels (8192 x 8192)");
    }
    // Within the limit the header passes and decoding reports the missing data.
    std::ofstream(path("wide.png"), std::ios::binary) << pngHeader(65536, 1024);
    EXPECT_EQ(ioErrorMessage([&] { readImage(path("wide.png")); }).rfind(
                  path("wide.png") + ": cannot decode the PNG file (", 0),
              0u);
}

TEST_F(ImageIoTest, aFifoOrDeviceIsRefusedBeforeOpening) {
    const texsplat::test::TestFifo png(path("pipe.png"));
    EXPECT_EQ(ioErrorMessage([&] { readImage(path("pipe.png")); }),
              path("pipe.png") + ": cannot read image file: it is a FIFO, not a regular file");
    if (!texsplat::image::isExrSupported())
        return;
    const texsplat::test::TestFifo exr(path("pipe.exr"));
    EXPECT_EQ(ioErrorMessage([&] { readImage(path("pipe.exr")); }),
              path("pipe.exr") + ": cannot read image file: it is a FIFO, not a regular file");
}

TEST_F(ImageIoTest, truncatedFilesAreIoErrors) {
    std::vector<std::string> names = {"full.png"};
    if (texsplat::image::isExrSupported())
        names.push_back("full.exr");
    for (const std::string& name : names) {
        writeImage(highDynamicRangeImage(), path(name));
        const auto size = fs::file_size(path(name));
        fs::resize_file(path(name), size / 2);
        EXPECT_THROW(readImage(path(name)), IoError) << name;
    }
}
