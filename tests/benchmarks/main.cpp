// The micro-benchmarks' main: Google Benchmark's own (same flags, same console/JSON/CSV output,
// same --benchmark_out file), followed by the time of each benchmark divided by the time of its
// baseline measured in the same run (RatioReporter; pairs declared next to the benchmarks with
// TEXSPLAT_BENCHMARK_BASELINE). The table goes to stdout after the console output, or to
// stderr when stdout carries JSON or CSV, so that those stay parseable.
#include "RatioReporter.h"

#include <benchmark/benchmark.h>

#include <memory>

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }
    // The reporter --benchmark_format asks for; the caller owns it (RunSpecifiedBenchmarks()
    // deletes it the same way when it makes it itself).
    const std::unique_ptr<benchmark::BenchmarkReporter> display(
        benchmark::CreateDefaultDisplayReporter());
    texsplat::microbench::RatioReporter reporter(*display);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    // JSON and CSV reporters are not ConsoleReporters.
    const bool isConsole = dynamic_cast<benchmark::ConsoleReporter*>(display.get()) != nullptr;
    reporter.printRatios(isConsole ? display->GetOutputStream() : display->GetErrorStream(),
                         benchmark::GetBenchmarkFilter());
    benchmark::Shutdown();
    return 0;
}
