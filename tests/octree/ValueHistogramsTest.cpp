#include "octree/ValueHistograms.h"

#include <gtest/gtest.h>

#include <array>
#include <bitset>
#include <cstdint>
#include <numeric>

namespace texsplat::octree {
namespace {

using Values = ValueHistograms::BlockValues;
using Mask = ValueHistograms::BlockMask;

TEST(ValueHistograms, sortsTheNonEmptyValuesIntoEqualBinsOverTheBlocksRange) {
    Values values{};
    Mask nonEmpty;
    // Values 2 + v / 100 at every third voxel; the others empty, with values that would land in
    // the bins if they were counted.
    float lowest = 1e9f;
    float highest = -1e9f;
    for (std::size_t v = 0; v < values.size(); ++v) {
        values[v] = v % 3 == 0 ? 2.0f + static_cast<float>(v) / 100.0f : 4.0f;
        nonEmpty[v] = v % 3 == 0;
        if (nonEmpty[v]) {
            lowest = std::min(lowest, values[v]);
            highest = std::max(highest, values[v]);
        }
    }
    const auto block =
        ValueHistograms::summarize(glm::u64vec3(1, 2, 3), values, nonEmpty, {lowest, highest});
    EXPECT_EQ(block.coordinates, glm::u64vec3(1, 2, 3));
    EXPECT_EQ(block.range, glm::vec2(lowest, highest));
    EXPECT_EQ(std::accumulate(block.counts.begin(), block.counts.end(), 0), 171);
    const float width = (highest - lowest) / ValueHistograms::kBins;
    for (int bin = 0; bin < ValueHistograms::kBins; ++bin) {
        SCOPED_TRACE(bin);
        EXPECT_GT(block.counts[static_cast<std::size_t>(bin)], 9); // about 171 / 16 each
        const float mean = block.means[static_cast<std::size_t>(bin)];
        EXPECT_GE(mean, lowest + static_cast<float>(bin) * width - 1e-5f);
        EXPECT_LE(mean, lowest + static_cast<float>(bin + 1) * width + 1e-5f);
    }
    EXPECT_EQ(block.counts.back(), 11) << "the largest value falls into the last bin";
}

TEST(ValueHistograms, keepsEqualValuesExactAndExtremeRangesFinite) {
    Values values{};
    Mask nonEmpty;
    values.fill(0.25f);
    nonEmpty.set();
    const auto uniform = ValueHistograms::summarize({}, values, nonEmpty, glm::vec2(0.25f));
    EXPECT_EQ(uniform.counts[0], 512);
    EXPECT_EQ(uniform.means[0], 0.25f);
    // A range whose width overflows float.
    values[0] = -3e38f;
    values[1] = 3e38f;
    const auto extreme = ValueHistograms::summarize({}, values, nonEmpty, {-3e38f, 3e38f});
    EXPECT_EQ(extreme.counts.front(), 1);
    EXPECT_EQ(extreme.means.front(), -3e38f);
    EXPECT_EQ(extreme.counts.back(), 1);
    EXPECT_EQ(extreme.means.back(), 3e38f);
    EXPECT_EQ(extreme.counts[ValueHistograms::kBins / 2], 510);
    EXPECT_EQ(extreme.means[ValueHistograms::kBins / 2], 0.25f);
}

} // namespace
} // namespace texsplat::octree
