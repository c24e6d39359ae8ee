#include "octree/DepthSort.h"

#include "octree/Splat.h"
#include "octree/View.h"
#include "scenegraph/Assert.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
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

} // namespace

void sortByDepth(SplatList& splats, const View& view) {
    const std::size_t count = splats.size();
    TEXSPLAT_ASSERT(count <= 0xFFFFFFFFu, "sortByDepth(): more than 2^32 splats (128 GiB)");
    // Each item packs the key above the splat's index, so the passes stream one array.
    std::vector<std::uint64_t> items(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 position(splats.splats()[i].position);
        const double depth = view.isPerspective() ? glm::distance(position, view.eye())
                                                  : glm::dot(position, view.direction());
        items[i] = std::uint64_t{farFirstKey(static_cast<float>(depth))} << 32 | i;
    }
    std::vector<std::uint64_t> scratch(count);
    // Four stable counting passes, one per key byte, least significant first; a byte that is
    // the same for every item needs no pass.
    for (int shift = 32; shift < 64; shift += 8) {
        std::array<std::size_t, 257> start{};
        for (const std::uint64_t item : items) {
            ++start[((item >> shift) & 0xFFu) + 1];
        }
        if (std::find(start.begin(), start.end(), count) != start.end()) {
            continue;
        }
        for (std::size_t bucket = 1; bucket < start.size(); ++bucket) {
            start[bucket] += start[bucket - 1];
        }
        for (const std::uint64_t item : items) {
            scratch[start[(item >> shift) & 0xFFu]++] = item;
        }
        std::swap(items, scratch);
    }
    SplatList sorted;
    sorted.reserve(count, splats.hasVectors());
    for (const std::uint64_t item : items) {
        const auto index = static_cast<std::size_t>(item & 0xFFFFFFFFu);
        if (splats.hasVectors()) {
            sorted.add(splats.splats()[index], splats.vectors()[index]);
        } else {
            sorted.add(splats.splats()[index]);
        }
    }
    splats = std::move(sorted);
}

} // namespace texsplat::octree
