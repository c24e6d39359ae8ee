// Classification through the TransferFunction: the whole grid at once (what ScalarSplat's
// cache does when the data or the transfer function change) against its natural baseline, the
// per-value classify() over the same values.
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"

#include "BenchmarkBaseline.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using texsplat::nodes::TransferFunction;
using texsplat::nodes::VolumeData;
using texsplat::nodes::VolumeSource;

texsplat::volume::ScalarGridPtr marschnerLobb(int resolution) {
    VolumeData::Ptr volume = VolumeData::create();
    volume->source.setValue(VolumeSource::MarschnerLobb);
    volume->resolution.setValue(glm::vec3(static_cast<float>(resolution)));
    return volume->scalarGrid();
}

// examples/marschner-lobb.iv's transfer function: about half the voxels are empty.
TransferFunction::Ptr transferFunction() {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->preset.setValue(texsplat::nodes::ColorPreset::Viridis);
    transfer->opacityValues.setValue({0.0f, 0.45f, 0.55f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.0f, 6.0f, 6.0f});
    transfer->validate();
    return transfer;
}

void ClassifyGrid(benchmark::State& state) {
    const auto grid = marschnerLobb(static_cast<int>(state.range(0)));
    const TransferFunction::Ptr transfer = transferFunction();
    for (auto _ : state) {
        benchmark::DoNotOptimize(transfer->classify(*grid));
    }
    state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0) * state.range(0));
}
BENCHMARK(ClassifyGrid)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

// Baseline: the per-value entry point over the same values (gathered once, outside the loop).
void ClassifyGridBaselinePerValue(benchmark::State& state) {
    const auto grid = marschnerLobb(static_cast<int>(state.range(0)));
    const TransferFunction::Ptr transfer = transferFunction();
    std::vector<float> values;
    values.reserve(static_cast<std::size_t>(state.range(0) * state.range(0) * state.range(0)));
    grid->forEachStored([&](const glm::i64vec3&, const float& value) { values.push_back(value); });
    std::vector<texsplat::nodes::Classification> out(values.size());
    for (auto _ : state) {
        for (std::size_t i = 0; i < values.size(); ++i) {
            out[i] = transfer->classify(values[i]);
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values.size()));
}
BENCHMARK(ClassifyGridBaselinePerValue)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);
TEXSPLAT_BENCHMARK_BASELINE(ClassifyGrid, ClassifyGridBaselinePerValue);

} // namespace
