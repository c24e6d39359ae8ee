#include "nodes/distributed/Compositor.h"

#include "DistributedTesting.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace texsplat::distributed {
namespace {

constexpr int kWidth = 37;
constexpr int kHeight = 29;

// Rank `rank`'s layer: a random region of the image (empty for every third rank from 2 on),
// random premultiplied pixels.
ImageLayer layerOf(int rank) {
    std::mt19937 random(static_cast<unsigned>(1000 + rank));
    ImageLayer layer;
    if (rank % 3 == 2) {
        return layer;
    }
    std::uniform_int_distribution<int> x(0, kWidth - 1);
    std::uniform_int_distribution<int> y(0, kHeight - 1);
    const int x0 = x(random);
    const int y0 = y(random);
    layer.region = {x0, y0, std::uniform_int_distribution<int>(1, kWidth - x0)(random),
                    std::uniform_int_distribution<int>(1, kHeight - y0)(random)};
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    layer.pixels.resize(std::size_t(layer.region.width) * std::size_t(layer.region.height));
    for (glm::vec4& pixel : layer.pixels) {
        pixel.a = unit(random);
        pixel = glm::vec4(pixel.a * unit(random), pixel.a * unit(random), pixel.a * unit(random),
                          pixel.a);
    }
    return layer;
}

// The ranks back to front, shuffled alike on every rank.
std::vector<int> shuffledOrder(int ranks) {
    std::vector<int> order(static_cast<std::size_t>(ranks));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    return order;
}

// The composite of every rank's layer in `order`, one pixel at a time in one process.
image::Pixels serialComposite(const std::vector<int>& order) {
    image::Pixels image(std::size_t(kWidth) * kHeight, glm::vec4(0.0f));
    for (const int rank : order) {
        const ImageLayer layer = layerOf(rank);
        for (int y = layer.region.y; y < layer.region.y + layer.region.height && !layer.isEmpty();
             ++y) {
            for (int x = layer.region.x; x < layer.region.x + layer.region.width; ++x) {
                glm::vec4& back = image[std::size_t(y) * kWidth + std::size_t(x)];
                const glm::vec4& front = layer.at(x, y);
                back = front + (1.0f - front.a) * back;
            }
        }
    }
    return image;
}

class CompositorTest : public ::testing::TestWithParam<Compositing> {};

TEST_P(CompositorTest, compositesTheRanksLayersInTheGivenOrder) {
    const std::vector<int> order = shuffledOrder(test::ranks());
    Compositor compositor(MPI_COMM_WORLD, kWidth, kHeight, GetParam());
    const image::Pixels image = compositor.composite(layerOf(test::rank()), order);
    if (test::rank() != 0) {
        EXPECT_TRUE(image.empty());
        return;
    }
    const image::Pixels expected = serialComposite(order);
    ASSERT_EQ(image.size(), expected.size());
    float largest = 0.0f;
    for (std::size_t i = 0; i < image.size(); ++i) {
        const glm::vec4 difference = glm::abs(image[i] - expected[i]);
        largest = std::max({largest, difference.r, difference.g, difference.b, difference.a});
    }
    EXPECT_LT(largest, 1e-5f); // the same "over", grouped otherwise
}

INSTANTIATE_TEST_SUITE_P(Methods, CompositorTest,
                         ::testing::Values(Compositing::RadixK, Compositing::Reduce),
                         [](const ::testing::TestParamInfo<Compositing>& method) {
                             return method.param == Compositing::RadixK ? std::string("radixK")
                                                                        : std::string("reduce");
                         });

TEST(Compositor, splitsTheRanksIntoRoundsOfSmallGroups) {
    EXPECT_EQ(Compositor::radixRounds(1), std::vector<int>{});
    EXPECT_EQ(Compositor::radixRounds(2), std::vector<int>{2});
    EXPECT_EQ(Compositor::radixRounds(5), std::vector<int>{5});
    EXPECT_EQ(Compositor::radixRounds(12), (std::vector<int>{4, 3}));
    EXPECT_EQ(Compositor::radixRounds(1024), (std::vector<int>{4, 4, 4, 4, 4}));
}

TEST(Compositor, namesItsMethods) {
    EXPECT_EQ(parseCompositing("radix-k", "--compositing"), Compositing::RadixK);
    EXPECT_EQ(parseCompositing("reduce", "--compositing"), Compositing::Reduce);
    EXPECT_EQ(toString(Compositing::Reduce), "reduce");
    try {
        parseCompositing("binary", "--compositing");
        FAIL() << "expected DataError";
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "--compositing: expected radix-k or reduce, got 'binary'");
    }
}

} // namespace
} // namespace texsplat::distributed
