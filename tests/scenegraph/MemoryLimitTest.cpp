#include "scenegraph/MemoryLimit.h"

#include "ScopedMemoryLimit.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <new>
#include <string>
#include <vector>

namespace texsplat {
namespace {

using test::ScopedMemoryLimit;

std::string errorOf(std::string_view text) {
    try {
        parseByteCount(text);
    } catch (const DataError& error) {
        return error.what();
    }
    return "no error";
}

} // namespace

TEST(MemoryLimit, byteCountsAreReadAsPeopleWriteThem) {
    EXPECT_EQ(parseByteCount("1000000"), 1000000u);
    EXPECT_EQ(parseByteCount("512M"), 512ull << 20);
    EXPECT_EQ(parseByteCount("8g"), 8ull << 30);
    EXPECT_EQ(parseByteCount("1.5GiB"), 3ull << 29);
    EXPECT_EQ(parseByteCount("64KB"), 64ull << 10);
    EXPECT_EQ(parseByteCount("2T"), 2ull << 40);
    EXPECT_EQ(parseByteCount("4096B"), 4096u);
    for (const char* bad : {"", "lots", "0", "-1M", "1..5G", "12Q", "1e9", "16777216T", "1BB",
                            "1BiB", "1.5", "1.5B", "1MM", "1iB"}) {
        EXPECT_EQ(errorOf(bad),
                  "expected a byte count such as 512M or 8G, got '" + std::string(bad) + "'");
    }
}

TEST(MemoryLimit, byteArithmeticSaturatesInsteadOfWrapping) {
    constexpr std::uint64_t kLargest = std::numeric_limits<std::uint64_t>::max();
    EXPECT_EQ(byteProduct(1000, 16), 16000u);
    EXPECT_EQ(byteProduct(0, 16), 0u);
    // A sparse grid's box of 6649655 x 442511 x 250759 voxels at 100 bytes each wraps to 3036
    // bytes in plain uint64 arithmetic, and passed every limit.
    const std::uint64_t voxels = byteProduct(byteProduct(6649655, 442511), 250759);
    EXPECT_EQ(voxels, 737869762948382095u);
    EXPECT_EQ(byteProduct(voxels, 100), kLargest);
    EXPECT_EQ(byteSum(kLargest - 1, 5), kLargest);
    EXPECT_EQ(byteSum(2, 3), 5u);
}

TEST(MemoryLimit, bytesTextGivesTheExactCountAndARoundedSize) {
    EXPECT_EQ(bytesText(512), "512 bytes (0.5 KiB)");
    EXPECT_EQ(bytesText(26214400), "26214400 bytes (25 MiB)");
    EXPECT_EQ(bytesText(12884901888ull), "12884901888 bytes (12 GiB)");
}

TEST(MemoryLimit, workAboveTheLimitIsRefusedBeforeItAllocates) {
    const ScopedMemoryLimit limit(1u << 20);
    EXPECT_EQ(memoryLimit(), 1u << 20);
    EXPECT_NO_THROW(checkMemory("a small grid", 1u << 20, "use less"));
    try {
        checkMemory("a grid of 1000000 voxels", 4000000, "use a smaller grid");
        FAIL() << "no error";
    } catch (const ResourceError& error) {
        EXPECT_STREQ(error.what(), "a grid of 1000000 voxels would need 4000000 bytes (3.81 MiB), "
                                   "more than the memory limit of 1048576 bytes (1 MiB); use a "
                                   "smaller grid");
    }
}

TEST(MemoryLimit, theDefaultLimitIsThePhysicalMemory) {
    const ScopedMemoryLimit limit(0);
    EXPECT_GT(memoryLimit(), 0u);
    EXPECT_GE(memoryLimit(), availableMemoryBytes());
}

TEST(MemoryLimit, runningOutOfMemoryInAStageSaysWhichStageHowMuchAndWhatToDo) {
    const ScopedMemoryLimit limit(1u << 30);
    try {
        withMemoryStage("classifying", 1u << 20, "use a smaller grid",
                        []() -> int { throw std::bad_alloc(); });
        FAIL() << "no error";
    } catch (const ResourceError& error) {
        EXPECT_STREQ(error.what(), "classifying: out of memory (this stage was estimated at "
                                   "1048576 bytes (1 MiB)); the memory limit is 1073741824 bytes "
                                   "(1 GiB); use a smaller grid");
    }
    // The innermost stage names itself; enclosing stages pass its error on.
    try {
        withMemoryStage("rendering", 0, "render less", [] {
            withMemoryStage("emitting splats", 0, "use a budget",
                            []() -> int { throw std::bad_alloc(); });
        });
        FAIL() << "no error";
    } catch (const ResourceError& error) {
        EXPECT_STREQ(error.what(), "emitting splats: out of memory; the memory limit is "
                                   "1073741824 bytes (1 GiB); use a budget");
    }
    EXPECT_EQ(withMemoryStage("adding", 0, "", [] { return 1 + 1; }), 2);
}

} // namespace texsplat
