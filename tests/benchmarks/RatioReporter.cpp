#include "RatioReporter.h"

#include "BenchmarkBaseline.h"

#include <algorithm>
#include <array>
#include <iomanip>
#include <sstream>

namespace texsplat::microbench {

RatioReporter::RatioReporter(benchmark::BenchmarkReporter& display) : mDisplay(display) {
    // RunSpecifiedBenchmarks() writes its own messages ("Failed to match any benchmarks", the
    // --benchmark_list_tests list) to the display reporter's streams: the same ones.
    SetOutputStream(&display.GetOutputStream());
    SetErrorStream(&display.GetErrorStream());
}

bool RatioReporter::ReportContext(const Context& context) {
    return mDisplay.ReportContext(context);
}

void RatioReporter::ReportRuns(const std::vector<Run>& runs) {
    mDisplay.ReportRuns(runs);
    for (const Run& run : runs) {
        Measurement& measured = measurement(run);
        if (run.error_occurred) {
            measured.error = run.error_message;
            continue;
        }
        // CPU time rather than wall time: on a shared machine it does not count the time the
        // thread waited for a core. Benchmarks of work on several threads (UseRealTime(): the
        // main thread's CPU time would miss the others') give wall time.
        const double time = run.run_name.time_type == "real_time" ? run.GetAdjustedRealTime()
                                                                  : run.GetAdjustedCPUTime();
        const double seconds = time / benchmark::GetTimeUnitMultiplier(run.time_unit);
        if (run.run_type == Run::RT_Iteration) {
            measured.iterationSeconds += seconds;
            ++measured.iterationRuns;
        } else if (run.aggregate_unit == benchmark::kTime && run.aggregate_name == "median") {
            measured.medianSeconds = seconds;
        } else if (run.aggregate_unit == benchmark::kTime && run.aggregate_name == "mean") {
            measured.meanSeconds = seconds;
        }
        // Other aggregates (stddev, cv, BigO, RMS) are not times per iteration.
    }
}

void RatioReporter::Finalize() { mDisplay.Finalize(); }

std::optional<double> RatioReporter::Measurement::seconds() const {
    if (!error.empty()) {
        return std::nullopt;
    }
    if (medianSeconds) {
        return medianSeconds;
    }
    if (meanSeconds) {
        return meanSeconds;
    }
    if (iterationRuns > 0) {
        return iterationSeconds / iterationRuns;
    }
    return std::nullopt;
}

RatioReporter::Measurement& RatioReporter::measurement(const Run& run) {
    const std::string name = run.run_name.str();
    const auto found = mIndexByName.find(name);
    if (found != mIndexByName.end()) {
        return mMeasurements[found->second];
    }
    mIndexByName.emplace(name, mMeasurements.size());
    Measurement& added = mMeasurements.emplace_back();
    added.runName = run.run_name;
    added.name = name;
    added.familyIndex = run.family_index;
    added.instanceIndex = run.per_family_instance_index;
    return added;
}

const RatioReporter::Measurement* RatioReporter::find(const std::string& name) const {
    const auto found = mIndexByName.find(name);
    return found == mIndexByName.end() ? nullptr : &mMeasurements[found->second];
}

std::string RatioReporter::ratioText(const Measurement& measured, const std::string& baselineName,
                                     const std::string& filter) const {
    if (!measured.error.empty()) {
        return "benchmark failed: " + measured.error;
    }
    const Measurement* baseline = find(baselineName);
    if (!baseline) {
        const std::string& baselineFunction = *baselineOf(measured.runName.function_name);
        const bool baselineRan =
            std::any_of(mMeasurements.begin(), mMeasurements.end(), [&](const Measurement& m) {
                return m.runName.function_name == baselineFunction;
            });
        if (baselineRan) {
            return "no ratio: the baseline did not run with the same arguments";
        }
        return "no ratio: baseline not run (--benchmark_filter=" + filter + " left it out)";
    }
    if (!baseline->error.empty()) {
        return "no ratio: baseline failed: " + baseline->error;
    }
    const std::optional<double> time = measured.seconds();
    const std::optional<double> baselineTime = baseline->seconds();
    if (!time || !baselineTime || !(*baselineTime > 0.0)) {
        return "no ratio: no time measured";
    }
    std::ostringstream text;
    text << std::showpoint << std::setprecision(3) << *time / *baselineTime;
    return text.str();
}

void RatioReporter::printRatios(std::ostream& out, const std::string& filter) const {
    if (mMeasurements.empty()) {
        return;
    }
    using Row = std::array<std::string, 3>;
    std::vector<Row> rows;
    rows.push_back({"benchmark", "its baseline", "time ratio (benchmark / baseline)"});
    std::vector<std::string> withoutBaseline;
    std::vector<const Measurement*> inRegistrationOrder;
    for (const Measurement& measured : mMeasurements) {
        inRegistrationOrder.push_back(&measured);
    }
    std::sort(inRegistrationOrder.begin(), inRegistrationOrder.end(),
              [](const Measurement* a, const Measurement* b) {
                  return a->familyIndex != b->familyIndex ? a->familyIndex < b->familyIndex
                                                          : a->instanceIndex < b->instanceIndex;
              });
    for (const Measurement* measuredPointer : inRegistrationOrder) {
        const Measurement& measured = *measuredPointer;
        const std::string* baselineFunction = baselineOf(measured.runName.function_name);
        if (!baselineFunction) {
            if (!isBaseline(measured.runName.function_name)) {
                withoutBaseline.push_back(measured.name);
            }
            continue;
        }
        benchmark::BenchmarkName baselineRun = measured.runName;
        baselineRun.function_name = *baselineFunction;
        const std::string baselineName = baselineRun.str();
        rows.push_back({measured.name, baselineName, ratioText(measured, baselineName, filter)});
    }

    out << "\nTime ratios against the baselines, measured in this run (CPU time per iteration, wall "
           "time for */real_time; the median over repetitions if any; below 1: faster than its "
           "baseline):\n";
    if (rows.size() == 1) {
        out << "(no benchmark with a baseline ran)\n";
    } else {
        std::array<std::size_t, 2> width{0, 0};
        for (const Row& row : rows) {
            width[0] = std::max(width[0], row[0].size());
            width[1] = std::max(width[1], row[1].size());
        }
        for (const Row& row : rows) {
            out << std::left << std::setw(static_cast<int>(width[0])) << row[0] << " | "
                << std::setw(static_cast<int>(width[1])) << row[1] << " | " << row[2] << '\n';
        }
    }
    if (!withoutBaseline.empty()) {
        out << "Measured without a baseline:";
        for (std::size_t i = 0; i < withoutBaseline.size(); ++i) {
            out << (i == 0 ? " " : ", ") << withoutBaseline[i];
        }
        out << '\n';
    }
    out << std::flush;
}

} // namespace texsplat::microbench
