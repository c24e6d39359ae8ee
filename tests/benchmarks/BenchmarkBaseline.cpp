#include "BenchmarkBaseline.h"

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
    baselines()[benchmarkName] = baselineName;
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
