// Splat emission: the full-resolution back-to-front list in slice order (every frame of a
// TextureSplat without a cut) against its natural baseline, the same splats emitted in memory
// order with no ordering at all; and the octree: build, and the cut a splat budget reaches.
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "octree/ClassifiedGrid.h"
#include "octree/DepthSort.h"
#include "octree/Cut.h"
#include "octree/Octree.h"
#include "octree/Refiner.h"
#include "octree/SliceOrder.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "octree/View.h"

#include "BenchmarkBaseline.h"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <tbb/task_arena.h>

#include <algorithm>
#include <memory>

namespace {

using texsplat::octree::ClassifiedGrid;
using texsplat::octree::SplatList;
using texsplat::octree::View;

std::shared_ptr<const ClassifiedGrid> classifiedMarschnerLobb(int resolution) {
    auto volume = texsplat::nodes::VolumeData::create();
    volume->source.setValue(texsplat::nodes::VolumeSource::MarschnerLobb);
    volume->resolution.setValue(glm::vec3(static_cast<float>(resolution)));
    auto transfer = texsplat::nodes::TransferFunction::create();
    transfer->opacityValues.setValue({0.0f, 0.45f, 0.55f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.0f, 6.0f, 6.0f});
    return transfer->classify(*volume->scalarGrid());
}

// An eye outside the grid's corner, looking obliquely at it (as `texsplat bench` does).
View obliqueView() {
    return View::perspective({-2.0, -2.5, 4.0}, {0.35, 0.5, -1.0});
}

void EmitVoxelSplatsSliceOrder(benchmark::State& state) {
    const auto grid = classifiedMarschnerLobb(static_cast<int>(state.range(0)));
    const View view = obliqueView();
    SplatList splats;
    for (auto _ : state) {
        texsplat::octree::emitVoxelSplats(*grid, view, splats);
        benchmark::DoNotOptimize(splats.splats().data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(splats.size()));
    state.counters["splats"] = static_cast<double>(splats.size());
}
BENCHMARK(EmitVoxelSplatsSliceOrder)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

// Baseline: the same splats in memory order (no view, no order, no culling).
void EmitVoxelSplatsBaselineMemoryOrder(benchmark::State& state) {
    const auto grid = classifiedMarschnerLobb(static_cast<int>(state.range(0)));
    const glm::u64vec3 dims = grid->dims();
    SplatList splats;
    for (auto _ : state) {
        splats.clear();
        for (std::uint64_t k = 0; k < dims.z; ++k) {
            for (std::uint64_t j = 0; j < dims.y; ++j) {
                for (std::uint64_t i = 0; i < dims.x; ++i) {
                    const glm::vec4 voxel = grid->voxel(glm::u64vec3(i, j, k));
                    if (voxel == glm::vec4(0.0f)) {
                        continue;
                    }
                    texsplat::octree::Splat splat;
                    splat.position = glm::vec3(grid->toWorld(glm::dvec3(i, j, k)));
                    splat.color = glm::vec3(voxel);
                    splat.extinction = voxel.w;
                    splats.add(splat);
                }
            }
        }
        benchmark::DoNotOptimize(splats.splats().data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(splats.size()));
    state.counters["splats"] = static_cast<double>(splats.size());
}
BENCHMARK(EmitVoxelSplatsBaselineMemoryOrder)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);
TEXSPLAT_BENCHMARK_BASELINE(EmitVoxelSplatsSliceOrder, EmitVoxelSplatsBaselineMemoryOrder);

// The slice order's walk alone, compared with the full emission that it is part of.
void SliceOrderWalk(benchmark::State& state) {
    const auto grid = classifiedMarschnerLobb(static_cast<int>(state.range(0)));
    const View view = obliqueView();
    for (auto _ : state) {
        const texsplat::octree::SliceOrder order(*grid, view);
        std::uint64_t sum = 0;
        order.forEach([&](const glm::u64vec3&, texsplat::octree::ClassifiedGrid::StorageIndex stored) {
            sum += stored;
        });
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() *
                            static_cast<std::int64_t>(grid->voxelCount()));
}
BENCHMARK(SliceOrderWalk)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);
TEXSPLAT_BENCHMARK_BASELINE(SliceOrderWalk, EmitVoxelSplatsSliceOrder);

void OctreeBuild(benchmark::State& state) {
    const auto grid = classifiedMarschnerLobb(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        benchmark::DoNotOptimize(std::make_unique<texsplat::octree::Octree>(grid));
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(grid->voxelCount()));
}
BENCHMARK(OctreeBuild)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

// The cut a splat budget reaches from the root, and its back-to-front emission.
void OctreeBudgetCutEmit(benchmark::State& state) {
    const auto grid = classifiedMarschnerLobb(128);
    const texsplat::octree::Octree octree(grid);
    const View view = obliqueView();
    SplatList splats;
    for (auto _ : state) {
        texsplat::octree::Refiner refiner(octree, view);
        texsplat::octree::RefineBudget budget;
        budget.maxSplats = static_cast<std::uint64_t>(state.range(0));
        refiner.refine(budget);
        texsplat::octree::emitSplats(refiner.cut(), view, splats);
        benchmark::DoNotOptimize(splats.splats().data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(splats.size()));
}
BENCHMARK(OctreeBudgetCutEmit)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

// The refinement alone, up to a quarter of Marschner-Lobb 128^3's 1.13 M voxels at the most.
void OctreeBudgetCut(benchmark::State& state) {
    const auto grid = classifiedMarschnerLobb(128);
    const texsplat::octree::Octree octree(grid);
    const View view = obliqueView();
    texsplat::octree::RefineBudget budget;
    budget.maxSplats = static_cast<std::uint64_t>(state.range(0));
    std::uint64_t splits = 0;
    for (auto _ : state) {
        texsplat::octree::Refiner refiner(octree, view);
        splits = refiner.refine(budget);
        benchmark::DoNotOptimize(refiner.cut().splatCount());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(splits));
    state.counters["splits"] = static_cast<double>(splits);
}
BENCHMARK(OctreeBudgetCut)
    ->Arg(100000)
    ->Arg(283000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime(); // as its parallel counterpart below

// The cut of the same budget made at once, on all threads (what a splat node does every frame),
// against the queue above.
void OctreeBudgetCutAtOnce(benchmark::State& state) {
    const auto grid = classifiedMarschnerLobb(128);
    const texsplat::octree::Octree octree(grid);
    const View view = obliqueView();
    const auto maxSplats = static_cast<std::uint64_t>(state.range(0));
    for (auto _ : state) {
        const texsplat::octree::Cut cut = texsplat::octree::Refiner::refineAtOnce(
            texsplat::octree::Cut(octree), view, maxSplats);
        benchmark::DoNotOptimize(cut.splatCount());
    }
}
BENCHMARK(OctreeBudgetCutAtOnce)
    ->Arg(100000)
    ->Arg(283000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
TEXSPLAT_BENCHMARK_BASELINE(OctreeBudgetCutAtOnce, OctreeBudgetCut);

// The back-to-front emission of a cut of a quarter of Marschner-Lobb 128^3's voxels, on all
// threads, against the same emission on one.
void emitCutSplats(benchmark::State& state, int threads) {
    const auto grid = classifiedMarschnerLobb(128);
    const texsplat::octree::Octree octree(grid);
    const View view = obliqueView();
    const texsplat::octree::Cut cut = texsplat::octree::Refiner::refineAtOnce(
        texsplat::octree::Cut(octree), view, static_cast<std::uint64_t>(state.range(0)));
    tbb::task_arena arena(threads);
    SplatList splats;
    for (auto _ : state) {
        arena.execute([&] { texsplat::octree::emitSplats(cut, view, splats); });
        benchmark::DoNotOptimize(splats.splats().data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(splats.size()));
}
void EmitCutSplats(benchmark::State& state) {
    emitCutSplats(state, tbb::task_arena::automatic);
}
BENCHMARK(EmitCutSplats)->Arg(283000)->Unit(benchmark::kMillisecond)->UseRealTime();
void EmitCutSplatsBaselineOneThread(benchmark::State& state) { emitCutSplats(state, 1); }
BENCHMARK(EmitCutSplatsBaselineOneThread)
    ->Arg(283000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
TEXSPLAT_BENCHMARK_BASELINE(EmitCutSplats, EmitCutSplatsBaselineOneThread);

// The centre-depth sort of an octree cut (what a splat node drawing a cut pays every frame):
// the radix sort with kept buffers against std::stable_sort by the same depths, both on one
// thread (the ratio is of CPU time; the sorter's passes would otherwise run on several). Both
// copy the unsorted list first.
SplatList marschnerLobbCut(std::uint64_t maxSplats) {
    const auto grid = classifiedMarschnerLobb(128);
    const texsplat::octree::Octree octree(grid);
    texsplat::octree::Refiner refiner(octree, obliqueView());
    texsplat::octree::RefineBudget budget;
    budget.maxSplats = maxSplats;
    refiner.refine(budget);
    SplatList splats;
    texsplat::octree::emitSplats(refiner.cut(), obliqueView(), splats);
    return splats;
}

void DepthSortCut(benchmark::State& state) {
    const SplatList unsorted = marschnerLobbCut(static_cast<std::uint64_t>(state.range(0)));
    texsplat::octree::DepthSorter sorter;
    tbb::task_arena oneThread(1);
    SplatList splats;
    for (auto _ : state) {
        splats = unsorted;
        oneThread.execute([&] { sorter.sort(splats, obliqueView()); });
        benchmark::DoNotOptimize(splats.splats().data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(unsorted.size()));
}
BENCHMARK(DepthSortCut)->Arg(283000)->Unit(benchmark::kMillisecond);

void DepthSortCutBaselineStableSort(benchmark::State& state) {
    const SplatList unsorted = marschnerLobbCut(static_cast<std::uint64_t>(state.range(0)));
    const View view = obliqueView();
    std::vector<texsplat::octree::Splat> splats;
    for (auto _ : state) {
        splats = unsorted.splats();
        std::stable_sort(splats.begin(), splats.end(), [&](const auto& a, const auto& b) {
            return static_cast<float>(glm::distance(glm::dvec3(a.position), view.eye())) >
                   static_cast<float>(glm::distance(glm::dvec3(b.position), view.eye()));
        });
        benchmark::DoNotOptimize(splats.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(unsorted.size()));
}
BENCHMARK(DepthSortCutBaselineStableSort)->Arg(283000)->Unit(benchmark::kMillisecond);
TEXSPLAT_BENCHMARK_BASELINE(DepthSortCut, DepthSortCutBaselineStableSort);

} // namespace
