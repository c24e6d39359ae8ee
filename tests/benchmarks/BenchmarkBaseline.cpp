#include "BenchmarkBaseline.h"

#include <cstdio>
#include <cstdlib>
#include <map>

namespace texsplat::microbench {
namespace {

// Benchmark function name → its baseline's. A function-local static: the declarations run
// during the static initialization of the other files, in no defined order.
std::map<std::string, std::string>& baselines() {
    static std::map<std::string, std::string> table;
    return table;
}

} // namespace

bool declareBaseline(const char* benchmarkName, BenchmarkFunction /*benchmark*/,
                     const char* baselineName, BenchmarkFunction /*baseline*/) {
    const auto [entry, isNew] = baselines().try_emplace(benchmarkName, baselineName);
    if (!isNew) {
        std::fprintf(stderr, "texsplat_microbench: %s has two baselines, %s and %s\n",
                     benchmarkName, entry->second.c_str(), baselineName);
        std::abort();
    }
    return true;
}

const std::string* baselineOf(const std::string& benchmarkName) {
    const auto found = baselines().find(benchmarkName);
    return found == baselines().end() ? nullptr : &found->second;
}

bool isBaseline(const std::string& functionName) {
    for (const auto& [benchmark, baseline] : baselines()) {
        if (baseline == functionName) {
            return true;
        }
    }
    return false;
}

} // namespace texsplat::microbench
