#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace texsplat::microbench {

/// @brief A display reporter that forwards everything to Google Benchmark's own (so the
/// console, JSON and CSV outputs and their flags stay as they are) and keeps each run's CPU
/// time per iteration, to print afterwards how each benchmark compares with the baseline
/// declared for it (TEXSPLAT_BENCHMARK_BASELINE, BenchmarkBaseline.h), both measured in this run.
class RatioReporter final : public benchmark::BenchmarkReporter {
public:
    /// @brief Forwards to `display`, which must outlive this reporter.
    explicit RatioReporter(benchmark::BenchmarkReporter& display);

    bool ReportContext(const Context& context) override;
    void ReportRuns(const std::vector<Run>& runs) override;
    void Finalize() override;

    /// @brief Prints the table "benchmark | its baseline | time ratio (benchmark / baseline)",
    /// one row per measured benchmark that has a baseline, in registration order (also under
    /// --benchmark_enable_random_interleaving), then the measured
    /// benchmarks without one. A baseline that did not run (left out by `filter`, the value of
    /// --benchmark_filter) or failed is said so in the ratio column. Prints nothing when no
    /// benchmark ran (e.g. --benchmark_list_tests).
    void printRatios(std::ostream& out, const std::string& filter) const;

private:
    // One benchmark instance ("ClassifyGrid/128"): its iteration runs and aggregates.
    struct Measurement {
        benchmark::BenchmarkName runName;
        std::string name; // runName.str()
        std::int64_t familyIndex = 0;   // registration order of the BENCHMARK()
        std::int64_t instanceIndex = 0; // and of its arguments
        double iterationSeconds = 0.0; // summed over the repetitions reported
        int iterationRuns = 0;
        std::optional<double> medianSeconds;
        std::optional<double> meanSeconds;
        std::string error;

        // The median over repetitions if there were any, else the mean; nullopt when failed.
        std::optional<double> seconds() const;
    };

    Measurement& measurement(const Run& run);
    const Measurement* find(const std::string& name) const;
    std::string ratioText(const Measurement& measured, const std::string& baselineName,
                          const std::string& filter) const;

    benchmark::BenchmarkReporter& mDisplay;
    std::vector<Measurement> mMeasurements; // in run order
    std::map<std::string, std::size_t> mIndexByName;
};

} // namespace texsplat::microbench
