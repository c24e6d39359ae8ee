#include "octree/detail/MarkPlaces.h"

#include <algorithm>

namespace texsplat::octree::detail {

void placeMarks(const std::vector<SplatMark>& marks, const std::vector<MarkPlace>& places,
                SplatList& splats) {
    std::vector<std::size_t> order;
    order.reserve(marks.size());
    for (std::size_t m = 0; m < marks.size(); ++m) {
        if (places[m].after != MarkPlace::kNowhere) {
            order.push_back(m);
        }
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return places[a].after != places[b].after ? places[a].after < places[b].after
                                                  : places[a].depth > places[b].depth;
    });
    const std::size_t count = splats.size();
    splats.resize(count, true, order.size());
    SplatMark* const outMarks = splats.writableMarks();
    std::uint32_t* const begins = splats.writableMarkBegins();
    std::size_t next = 0;
    for (std::size_t i = 0; i <= count; ++i) {
        begins[i] = static_cast<std::uint32_t>(next);
        while (i < count && next < order.size() && places[order[next]].after == i) {
            outMarks[next] = marks[order[next]];
            ++next;
        }
    }
}

} // namespace texsplat::octree::detail
