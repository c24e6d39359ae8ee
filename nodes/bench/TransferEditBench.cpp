#include "nodes/bench/TransferEditBench.h"

#include "nodes/ScalarSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "octree/ValueRanges.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/SearchAction.h"

#include <chrono>
#include <cstdio>

namespace texsplat::bench {
namespace {

using Clock = std::chrono::steady_clock;

template <class T> std::vector<T*> nodesOf(sg::Node& root) {
    sg::SearchAction search;
    search.setType(T::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.apply(root);
    std::vector<T*> found;
    for (const sg::Path& path : search.paths()) {
        found.push_back(&static_cast<T&>(*path.tail()));
    }
    return found;
}

struct Edit {
    const char* name;
    void (*apply)(nodes::TransferFunction&);
};

void halveOpacities(nodes::TransferFunction& transfer) {
    std::vector<float> opacities = transfer.opacities.values();
    for (float& opacity : opacities) {
        opacity *= 0.5f;
    }
    transfer.opacities.setValue(std::move(opacities));
}

void raiseRangeMinimum(nodes::TransferFunction& transfer) {
    const glm::vec2 range = transfer.range.value();
    transfer.rangeMode.setValue(nodes::RangeMode::Fixed);
    transfer.range.setValue(glm::vec2(range.x + 0.3f * (range.y - range.x), range.y));
}

constexpr Edit kEdits[] = {{"opacities x 0.5", halveOpacities},
                           {"range from 30 %", raiseRangeMinimum}};

// A CPU frame of `root`: its wall time less loading, and its statistics.
struct Timed {
    double seconds = 0.0;
    sg::RenderStatistics statistics;
};

Timed timeFrame(sg::Node& root, glm::ivec2 size, const render::cpu::CpuRenderer& renderer) {
    render::FrameAction action(size.x, size.y);
    const Clock::time_point start = Clock::now();
    renderer.draw(action.collect(root), action.statistics(), false);
    Timed timed;
    timed.seconds = std::chrono::duration<double>(Clock::now() - start).count() -
                    action.statistics().time(sg::RenderPhase::Load);
    timed.statistics = action.statistics();
    return timed;
}

// Sets every splat node's budget and applies `edits` to every transfer function of `root`.
void prepare(sg::Node& root, std::uint64_t maxSplats, const std::vector<const Edit*>& edits) {
    const std::vector<nodes::ScalarSplat*> splats = nodesOf<nodes::ScalarSplat>(root);
    const std::vector<nodes::TransferFunction*> transfers = nodesOf<nodes::TransferFunction>(root);
    if (splats.empty() || transfers.empty()) {
        throw DataError("bench --transfer-edit: the scene needs a TransferFunction and a splat "
                        "node");
    }
    for (nodes::ScalarSplat* splat : splats) {
        splat->maxSplats.setValue(static_cast<int>(maxSplats));
    }
    for (const Edit* edit : edits) {
        for (nodes::TransferFunction* transfer : transfers) {
            edit->apply(*transfer);
        }
    }
}

double valueRangeSeconds(sg::Node& root) {
    const Clock::time_point start = Clock::now();
    for (const nodes::VolumeData* volume : nodesOf<nodes::VolumeData>(root)) {
        const volume::ScalarGridPtr grid = volume->scalarGrid();
        octree::ValueRanges ranges(glm::u64vec3(grid->geometry().dims()));
        grid->forEachActive([&ranges](const glm::i64vec3& index, float value) {
            ranges.add(glm::u64vec3(index), value);
        });
    }
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

std::vector<TransferEditTime> measureTransferEdit(const std::function<sg::Node::Ptr()>& makeScene,
                                                  glm::ivec2 size,
                                                  const std::vector<std::uint64_t>& maxSplats,
                                                  int threads) {
    const render::cpu::CpuRenderer renderer(threads);
    std::vector<TransferEditTime> rows;
    for (const std::uint64_t budget : maxSplats) {
        for (const Edit& edit : kEdits) {
            const sg::Node::Ptr scene = makeScene();
            prepare(*scene, budget, {});
            timeFrame(*scene, size, renderer); // loads, classifies, builds what the budget needs
            prepare(*scene, budget, {&edit});
            const Timed edited = timeFrame(*scene, size, renderer);
            // A fresh copy while `scene` holds the grids: they are shared, not loaded again.
            const sg::Node::Ptr fresh = makeScene();
            prepare(*fresh, budget, {&edit});
            TransferEditTime row;
            row.edit = edit.name;
            row.maxSplats = budget;
            row.splats = edited.statistics.splats;
            row.editSeconds = edited.seconds;
            row.editValueRanges = edited.statistics.builds.valueRanges;
            row.valueRangeSeconds = valueRangeSeconds(*fresh);
            row.rebuildSeconds = timeFrame(*fresh, size, renderer).seconds;
            rows.push_back(row);
        }
    }
    return rows;
}

std::string transferEditTable(const std::vector<TransferEditTime>& rows) {
    std::string table = "edit              budget     splats   after edit   fresh nodes "
                        "(value ranges)   fresh/edit  ranges rebuilt\n";
    for (const TransferEditTime& row : rows) {
        char line[256];
        std::snprintf(line, sizeof line,
                      "%-16s %7s %10zu   %8.3f s   %8.3f s (%8.3f s)   %8.2f   %zu\n",
                      row.edit.c_str(),
                      row.maxSplats == 0 ? "full" : std::to_string(row.maxSplats).c_str(),
                      row.splats, row.editSeconds, row.rebuildSeconds, row.valueRangeSeconds,
                      row.rebuildSeconds / row.editSeconds, row.editValueRanges);
        table += line;
    }
    return table;
}

} // namespace texsplat::bench
