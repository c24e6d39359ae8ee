// Footprint evaluation of the kernel: the closed form f(r) of the paper's cubic (what
// FootprintTexture tabulates and the polygonal splat samples) against its natural baseline,
// the bilinear lookup in the 64² footprint texture that the texture splats sample per pixel.
#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/GaussianKernel.h"
#include "nodes/kernel/KernelOptimizer.h"

#include "BenchmarkBaseline.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <vector>

namespace {

using texsplat::kernel::CubicKernel;
using texsplat::kernel::FootprintTexture;

constexpr int kPoints = 4096;

// Points spread over the splat's quad [-1.6, 1.6]², about a fifth outside the support.
std::vector<std::array<double, 2>> samplePoints() {
    std::vector<std::array<double, 2>> points;
    points.reserve(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        const double u = std::fmod(0.618033988749895 * i, 1.0);
        const double v = std::fmod(0.754877666246693 * i, 1.0);
        points.push_back({3.2 * u - 1.6, 3.2 * v - 1.6});
    }
    return points;
}

void FootprintClosedFormCubic(benchmark::State& state) {
    const CubicKernel kernel = CubicKernel::paper();
    const auto points = samplePoints();
    for (auto _ : state) {
        double sum = 0.0;
        for (const auto& p : points) {
            sum += kernel.footprint(std::hypot(p[0], p[1]));
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(FootprintClosedFormCubic);

void FootprintClosedFormGaussian(benchmark::State& state) {
    const auto gaussian =
        texsplat::kernel::KernelOptimizer().fitGaussian(CubicKernel::paper().support()).kernel;
    const auto points = samplePoints();
    for (auto _ : state) {
        double sum = 0.0;
        for (const auto& p : points) {
            sum += gaussian.footprint(std::hypot(p[0], p[1]));
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(FootprintClosedFormGaussian);

// Baseline: the bilinear texture lookup (FootprintTexture::sample, GL_LINEAR + CLAMP_TO_EDGE).
void FootprintBaselineTextureLookup(benchmark::State& state) {
    const FootprintTexture texture(CubicKernel::paper(), 64);
    const auto points = samplePoints();
    for (auto _ : state) {
        double sum = 0.0;
        for (const auto& p : points) {
            sum += texture.sample(p);
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(FootprintBaselineTextureLookup);
TEXSPLAT_BENCHMARK_BASELINE(FootprintClosedFormCubic, FootprintBaselineTextureLookup);
TEXSPLAT_BENCHMARK_BASELINE(FootprintClosedFormGaussian, FootprintBaselineTextureLookup);

// Tabulating the texture (what TextureSplat does when its batch is made).
void FootprintTextureBuild(benchmark::State& state) {
    const CubicKernel kernel = CubicKernel::paper();
    for (auto _ : state) {
        benchmark::DoNotOptimize(FootprintTexture(kernel, static_cast<int>(state.range(0))));
    }
    state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0));
}
BENCHMARK(FootprintTextureBuild)->Arg(64)->Arg(256);

} // namespace
