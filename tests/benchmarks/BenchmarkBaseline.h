#pragma once

// How a micro-benchmark names its baseline: once, next to the two registrations,
//
//     BENCHMARK(ClassifyGrid)->Arg(64)->Arg(128);
//     BENCHMARK(ClassifyGridBaselinePerValue)->Arg(64)->Arg(128);
//     TEXSPLAT_BENCHMARK_BASELINE(ClassifyGrid, ClassifyGridBaselinePerValue);
//
// The macro takes the benchmark functions themselves, so a misspelt or removed one does not
// compile, and records the pair by function name during static initialization. After the run,
// the microbench's main (RatioReporter) divides each run of a benchmark by the run of its
// baseline with the same arguments: "ClassifyGrid/128" by "ClassifyGridBaselinePerValue/128".
// A benchmark has at most one baseline (a second declaration for it in the same file does not
// compile, the variable the macro defines being named after the benchmark; one in another file
// stops the microbench at start-up); a baseline may serve several.

#include <benchmark/benchmark.h>

#include <string>

namespace texsplat::microbench {

/// @brief What BENCHMARK() registers: a function of the benchmark's state.
using BenchmarkFunction = void (*)(benchmark::State&);

/// @brief Records that the runs of the benchmark function `benchmarkName` are compared with
/// those of `baselineName`; use TEXSPLAT_BENCHMARK_BASELINE rather than calling it. The function
/// pointers are only there so that both names must be real functions. Returns true.
bool declareBaseline(const char* benchmarkName, BenchmarkFunction benchmark,
                     const char* baselineName, BenchmarkFunction baseline);

/// @brief The baseline function name declared for the benchmark function `benchmarkName`, or
/// nullptr when it has none.
const std::string* baselineOf(const std::string& benchmarkName);

/// @brief Whether `functionName` is declared as the baseline of some benchmark.
bool isBaseline(const std::string& functionName);

} // namespace texsplat::microbench

/// @brief Declares `baselineFunction` as the baseline of `benchmarkFunction` (both registered
/// with BENCHMARK() in the same file, above); see the top of BenchmarkBaseline.h.
#define TEXSPLAT_BENCHMARK_BASELINE(benchmarkFunction, baselineFunction)                      \
    [[maybe_unused]] const bool kBaselineOf##benchmarkFunction =                              \
        ::texsplat::microbench::declareBaseline(#benchmarkFunction, benchmarkFunction,        \
                                                #baselineFunction, baselineFunction)
