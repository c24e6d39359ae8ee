#include "octree/DepthSort.h"

#include "octree/View.h"
#include "scenegraph/Assert.h"

#include <glm/geometric.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <utility>
#include <vector>

namespace texsplat::octree {

namespace {

// Maps a float to an unsigned key with the same order (negative floats reversed), then inverts
// it so that ascending keys are decreasing depths: the farthest splat sorts first.
std::uint32_t farFirstKey(float depth) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &depth, sizeof bits);
    const std::uint32_t ascending = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
    return ~ascending;
}

// Items per chunk of a radix pass: each chunk counts its own digits, then writes them where the
// counts of the chunks before it end, so the passes are stable on any number of threads.
constexpr std::size_t kChunk = std::size_t{1} << 15;

using Histogram = std::array<std::size_t, 256>;

// One stable counting pass over the key byte at @p shift from @p items to @p scratch; false
// (and nothing written) when every item has the same byte there.
bool radixPass(const std::vector<std::uint64_t>& items, std::vector<std::uint64_t>& scratch,
               int shift) {
    const std::size_t count = items.size();
    const std::size_t chunks = (count + kChunk - 1) / kChunk;
    std::vector<Histogram> starts(chunks);
    const auto digit = [shift](std::uint64_t item) {
        return static_cast<std::size_t>((item >> shift) & 0xFFu);
    };
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t chunk) {
        Histogram histogram{};
        const std::size_t end = std::min(count, (chunk + 1) * kChunk);
        for (std::size_t i = chunk * kChunk; i < end; ++i) {
            ++histogram[digit(items[i])];
        }
        starts[chunk] = histogram;
    });
    for (std::size_t bucket = 0; bucket < 256; ++bucket) {
        std::size_t total = 0;
        for (const Histogram& start : starts) {
            total += start[bucket];
        }
        if (total == count) {
            return false;
        }
    }
    // Bucket by bucket, chunk by chunk: where each chunk's items of each bucket start.
    std::size_t next = 0;
    for (std::size_t bucket = 0; bucket < 256; ++bucket) {
        for (Histogram& start : starts) {
            const std::size_t inChunk = start[bucket];
            start[bucket] = next;
            next += inChunk;
        }
    }
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t chunk) {
        Histogram& start = starts[chunk];
        const std::size_t end = std::min(count, (chunk + 1) * kChunk);
        for (std::size_t i = chunk * kChunk; i < end; ++i) {
            scratch[start[digit(items[i])]++] = items[i];
        }
    });
    return true;
}

} // namespace

void sortByDepth(SplatList& splats, const View& view) {
    DepthSorter().sort(splats, view);
}

void DepthSorter::sort(SplatList& splats, const View& view) {
    const std::size_t count = splats.size();
    TEXSPLAT_ASSERT(count <= 0xFFFFFFFFu, "sortByDepth(): more than 2^32 splats (128 GiB)");
    const bool withMarks = splats.hasMarks();
    const Splat* const from = splats.splats().data();
    mItems.resize(count);
    mScratch.resize(count);
    using Range = tbb::blocked_range<std::size_t>;
    // Each item packs the key above the splat's index, so the passes stream one array.
    tbb::parallel_for(Range(0, count, kChunk), [&](const Range& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            const glm::dvec3 position(from[i].position);
            const double depth = view.isPerspective() ? glm::distance(position, view.eye())
                                                      : glm::dot(position, view.direction());
            mItems[i] = std::uint64_t{farFirstKey(static_cast<float>(depth))} << 32 | i;
        }
    });
    // Four stable passes, one per key byte, least significant first; a byte that is the same for
    // every item needs no pass.
    for (int shift = 32; shift < 64; shift += 8) {
        if (radixPass(mItems, mScratch, shift)) {
            std::swap(mItems, mScratch);
        }
    }
    // The sorted marks' offsets: each splat's count in the new order, summed.
    std::vector<std::uint32_t>& begins = mMarkBegins;
    begins.assign(withMarks ? count + 1 : 0, 0);
    if (withMarks) {
        tbb::parallel_for(Range(0, count, kChunk), [&](const Range& range) {
            for (std::size_t i = range.begin(); i < range.end(); ++i) {
                const auto index = static_cast<std::size_t>(mItems[i] & 0xFFFFFFFFu);
                begins[i + 1] = static_cast<std::uint32_t>(splats.markBegin(index + 1) -
                                                           splats.markBegin(index));
            }
        });
        std::partial_sum(begins.begin(), begins.end(), begins.begin());
    }
    mSorted.resize(count, withMarks, splats.marks().size());
    Splat* const to = mSorted.writableSplats();
    SplatMark* const toMarks = mSorted.writableMarks();
    std::uint32_t* const toBegins = mSorted.writableMarkBegins();
    tbb::parallel_for(Range(0, count, kChunk), [&](const Range& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            const auto index = static_cast<std::size_t>(mItems[i] & 0xFFFFFFFFu);
            to[i] = from[index];
            if (withMarks) {
                const SplatMark* marks = splats.marks().data();
                std::copy(marks + splats.markBegin(index), marks + splats.markBegin(index + 1),
                          toMarks + begins[i]);
                toBegins[i] = begins[i];
            }
        }
    });
    if (withMarks) {
        toBegins[count] = begins[count];
    }
    std::swap(splats, mSorted);
}

std::uint64_t DepthSorter::memoryBytes() const {
    return (mItems.capacity() + mScratch.capacity()) * sizeof(std::uint64_t) +
           mMarkBegins.capacity() * sizeof(std::uint32_t) + mSorted.memoryBytes();
}

} // namespace texsplat::octree
