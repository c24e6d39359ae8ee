// The CPU backend's inner loop: render::cpu::compositeSplats() (SIMD through Highway, the
// instruction set picked at run time) against its baseline, the plain scalar loop that
// composites the same set-up splats the same way (tests/nodes/SplatSpansReference.h; the
// nodes tests hold the two to the same image). The splats are those `texsplat bench` draws with
// the paper's texture splats in a 512² image: blob64 seen orthographically (one affine map) and
// in perspective (a homography per splat), squares about 8 pixels from the centre; blob128 in
// perspective, about 4 pixels, where a splat's rows are short for the SIMD vectors; and the
// issue's measure, Marschner–Lobb 128³, orthographic (boxes 9–10 pixels wide) and in
// perspective (mostly 7–8). Orthographic splats are stamped, as CpuRenderer draws them
// (FootprintStamps: the footprint tabulated per sub-pixel phase), or looked up exactly per pixel
// (the fourth argument 0). Both paths composite all rows on one thread into the same planes
// again and again (the work per pixel does not depend on what the planes hold); fragments are
// the pixels inside a square (stamped: where the footprint is not 0), counted once by the
// scalar loop.
//
// The orthographic stamped workloads are also drawn as CpuRenderer draws a full-resolution
// batch: compositeVoxels() walks the grid's voxels in slice order, band by band, and places
// each splat from its voxel's index on the way (no list, no set-up beforehand). Its baseline is
// compositeSplats() of the same splats set up beforehand: the ratio is what walking and placing
// costs on top of the compositing (the same pixels, the same bytes).
#include "nodes/render/cpu/SplatSpans.h"
#include "nodes/render/cpu/VoxelRaster.h"
#include "nodes/render/cpu/VoxelSpans.h"

#include "tests/nodes/SplatSpansReference.h"

#include "BenchmarkBaseline.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>

namespace {

using texsplat::render::cpu::ColorPlanes;
using texsplat::test::CompositeWorkload;
using texsplat::test::WorkloadCamera;

constexpr int kImageSize = 512;

// A workload with its fragment count, made once per dataset and camera for all the benchmarks.
struct TimedWorkload {
    CompositeWorkload workload;
    std::uint64_t fragments = 0;
};

const TimedWorkload& timedWorkload(const std::string& dataset, WorkloadCamera camera,
                                   bool stamped) {
    static std::map<std::tuple<std::string, WorkloadCamera, bool>, TimedWorkload> workloads;
    auto found = workloads.find({dataset, camera, stamped});
    if (found == workloads.end()) {
        TimedWorkload timed;
        timed.workload = texsplat::test::compositeWorkload(dataset, "texture", camera, kImageSize,
                                                           true, stamped);
        ColorPlanes planes(kImageSize, kImageSize, glm::vec4(0.0f), false);
        timed.fragments = texsplat::test::compositeSplatsScalar(
            timed.workload.splats.data(), timed.workload.splats.size(), *timed.workload.sampler,
            timed.workload.stamps(), planes, 0, kImageSize);
        found = workloads.emplace(std::make_tuple(dataset, camera, stamped), std::move(timed))
                    .first;
    }
    return found->second;
}

// Times `composite` (`path` names it in the label) over the workload of the benchmark's
// arguments: the camera (0: orthographic, 1: perspective), the resolution, the dataset (0: the
// blob, 1: Marschner–Lobb, the measure) and whether orthographic splats are stamped;
// reports fragments per second.
template <typename Composite>
void timeComposite(benchmark::State& state, const Composite& composite, const std::string& path) {
    const WorkloadCamera camera =
        state.range(0) == 0 ? WorkloadCamera::Orthographic : WorkloadCamera::Perspective;
    const std::string dataset =
        (state.range(2) == 0 ? "blob" : "ml") + std::to_string(state.range(1));
    const bool stamped = state.range(3) != 0;
    const TimedWorkload& timed = timedWorkload(dataset, camera, stamped);
    const CompositeWorkload& workload = timed.workload;
    ColorPlanes planes(workload.width, workload.height, glm::vec4(0.0f), false);
    for (auto _ : state) {
        composite(workload, planes);
        benchmark::DoNotOptimize(planes.alpha(0));
        benchmark::ClobberMemory();
    }
    const auto fragments = static_cast<double>(timed.fragments);
    state.SetLabel(dataset +
                   (camera == WorkloadCamera::Orthographic
                        ? (stamped ? " orthographic, stamped, " : " orthographic, exact, ")
                        : " perspective, ") +
                   path);
    state.counters["fragments/s"] =
        benchmark::Counter(fragments, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["splats"] = static_cast<double>(workload.splats.size());
    state.counters["fragments/splat"] = fragments / static_cast<double>(workload.splats.size());
}

// The workloads of both paths (timeComposite's arguments).
void workloads(benchmark::internal::Benchmark* benchmark) {
    benchmark->Args({0, 64, 0, 1})
        ->Args({0, 64, 0, 0})
        ->Args({1, 64, 0, 0})
        ->Args({1, 128, 0, 0})
        ->Args({0, 128, 1, 1})
        ->Args({0, 128, 1, 0})
        ->Args({1, 128, 1, 0});
}

void CompositeSplatsSimd(benchmark::State& state) {
    timeComposite(
        state,
        [](const CompositeWorkload& workload, ColorPlanes& planes) {
            texsplat::render::cpu::compositeSplats(workload.splats.data(), workload.rows.data(),
                                                   workload.splats.size(),
                                                   workload.sampler.get(), workload.stamps(),
                                                   nullptr, planes, 0, workload.height);
        },
        texsplat::render::cpu::compositeTarget());
}
BENCHMARK(CompositeSplatsSimd)
    ->Apply(workloads)
    ->Unit(benchmark::kMillisecond);

// Baseline: the scalar reference, one pixel at a time, std::expm1 for every fragment.
void CompositeSplatsBaselineScalar(benchmark::State& state) {
    timeComposite(
        state,
        [](const CompositeWorkload& workload, ColorPlanes& planes) {
            texsplat::test::compositeSplatsScalar(workload.splats.data(), workload.splats.size(),
                                                  *workload.sampler, workload.stamps(), planes, 0,
                                                  workload.height);
        },
        "scalar");
}
BENCHMARK(CompositeSplatsBaselineScalar)
    ->Apply(workloads)
    ->Unit(benchmark::kMillisecond);
TEXSPLAT_BENCHMARK_BASELINE(CompositeSplatsSimd, CompositeSplatsBaselineScalar);

// The voxel walk over the orthographic stamped workloads, band by band as CpuRenderer's bands
// (at most 64 rows), all on one thread.
void CompositeVoxelsWalk(benchmark::State& state) {
    timeComposite(
        state,
        [](const CompositeWorkload& workload, ColorPlanes& planes) {
            const texsplat::render::cpu::VoxelRaster voxels(
                *workload.voxels, *workload.setup, *workload.sampler, workload.width,
                workload.height);
            constexpr int kBandRows = 64;
            for (int row = 0; row < workload.height; row += kBandRows) {
                texsplat::render::cpu::compositeVoxels(
                    voxels, planes, row, std::min(workload.height, row + kBandRows));
            }
        },
        std::string("voxel walk, ") + texsplat::render::cpu::compositeTarget());
}
BENCHMARK(CompositeVoxelsWalk)
    ->Args({0, 64, 0, 1})
    ->Args({0, 128, 1, 1})
    ->Unit(benchmark::kMillisecond);
TEXSPLAT_BENCHMARK_BASELINE(CompositeVoxelsWalk, CompositeSplatsSimd);

} // namespace
