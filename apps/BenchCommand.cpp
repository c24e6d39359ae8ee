#include "apps/Commands.h"
#include "apps/MemoryLimitOption.h"

#include "apps/OptionError.h"
#include "apps/SceneSetup.h"
#include "apps/ThreadLimit.h"

#include "nodes/bench/BenchReport.h"
#include "nodes/bench/BenchRunner.h"
#include "nodes/bench/LegibilityBench.h"
#include "nodes/bench/TransferEditBench.h"
#include "nodes/render/BackendChoice.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "scenegraph/AtomicFile.h"
#include "scenegraph/Error.h"
#include "scenegraph/FileExtension.h"
#include "scenegraph/MemoryLimit.h"
#ifdef TEXSPLAT_WITH_GL
#include "scenegraph/gl/EglContext.h"
#endif

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <unistd.h>

namespace texsplat::apps {
namespace {

using Clock = std::chrono::steady_clock;

struct BenchArguments {
    std::string datasets = "ml128,tornado128";
    std::string sizes = "512x512";
    std::string methods = "texture,texture-gaussian,polygon,texture@0.25,texture@0.05";
    int repeat = 5;
    int warmup = 1;
    int threads = 0;
    std::string backends = "auto";
    bool noReference = false;
    std::string csv;
    std::string plot;
    std::string memoryLimit;
    std::string scene; // "" for the built-in datasets
    bool datasetGiven = false;
    bool methodGiven = false;
    bool backendGiven = false;
    bool budgetsGiven = false;
    std::string budgets = "1,0.5,0.2,0.1,0.05,0.02";
    int transferEdit = 0;    // splats of the budgeted frame after an edit; 0: not asked
    std::string images;      // with --transfer-edit or --legibility: the folder its frames go to
    bool legibility = false; // the legibility of vector marks instead of error against time
    Framing framing;
};

std::vector<glm::ivec2> parseSizes(const std::string& text) {
    std::vector<glm::ivec2> sizes;
    std::istringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        sizes.push_back(parseSize(item));
    }
    if (sizes.empty()) {
        throw DataError("--size: expected WxH with whole numbers from 1 to 16384, got ''");
    }
    return sizes;
}

// Progress on stderr: one updating line on a terminal, a line per finished stage otherwise.
class ProgressPrinter {
public:
    ProgressPrinter() : mTerminal(isatty(STDERR_FILENO) == 1) {}

    void operator()(const std::string& stage, double fraction) {
        if (stage != mStage) {
            mStage = stage;
            mStart = Clock::now();
        }
        const double seconds = std::chrono::duration<double>(Clock::now() - mStart).count();
        if (mTerminal) {
            std::fprintf(stderr, "\r%-60s %3.0f%% %6.1f s%s", stage.c_str(), 100.0 * fraction,
                         seconds, fraction >= 1.0 ? "\n" : "");
        } else if (fraction >= 1.0) {
            std::fprintf(stderr, "%s: %.1f s\n", stage.c_str(), seconds);
        }
        std::fflush(stderr);
    }

private:
    bool mTerminal;
    std::string mStage;
    Clock::time_point mStart;
};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::istringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        items.push_back(item);
    }
    return items;
}

std::vector<double> parseBudgets(const std::string& text) {
    const std::string message =
        "--budgets: expected fractions in (0, 1], e.g. 1,0.1,0.01, got '" + text + "'";
    std::vector<double> budgets;
    for (const std::string& item : splitList(text)) {
        double value = 0.0;
        const char* end = item.data() + item.size();
        const auto [parsed, error] = std::from_chars(item.data(), end, value);
        if (item.empty() || error != std::errc() || parsed != end || !(value > 0.0) ||
            value > 1.0) {
            throw DataError(message);
        }
        budgets.push_back(value);
    }
    if (budgets.empty()) {
        throw DataError(message);
    }
    return budgets;
}

// The devices of the run, for the header line and the plot: the GL context, the CPU backend.
std::string deviceSummary(const bench::BenchOptions& options,
                          [[maybe_unused]] const gl::EglContext* context) {
    std::string text;
    for (const render::Backend backend : options.backends) {
        text += text.empty() ? "" : "; ";
        if (backend == render::Backend::Gl) {
#ifdef TEXSPLAT_WITH_GL
            text += "GL " + context->info().summary() + " (" + context->info().platform + ")";
#endif
        } else {
            text += render::cpu::CpuRenderer(options.cpuThreads).description();
        }
    }
    return text;
}

// The user's scene with its own camera, or one framing it as `render` does (for the first size).
sg::Node::Ptr sceneToMeasure(const BenchArguments& arguments) {
    const glm::ivec2 size = parseSizes(arguments.sizes).front();
    Framing framing = arguments.framing;
    framing.sceneName = arguments.scene;
    return withCamera(loadScene(arguments.scene), framing,
                      static_cast<float>(size.x) / static_cast<float>(size.y));
}

// The option values of `bench`, checked before any work.
struct CheckedBench {
    bench::BenchOptions options; // all but the backends, which need a device to resolve
    std::vector<double> budgets; // with a SCENE
    std::uint64_t memoryLimit;
};

CheckedBench checkBenchOptions(const BenchArguments& arguments) {
    const bool isScene = !arguments.scene.empty();
    if (!arguments.images.empty() && arguments.transferEdit == 0 && !arguments.legibility) {
        throw DataError("--images: only with --transfer-edit or --legibility (it writes the "
                        "frames they measure)");
    }
    if (arguments.legibility && (isScene || arguments.transferEdit > 0 || arguments.datasetGiven ||
                                 arguments.methodGiven || arguments.budgetsGiven)) {
        throw DataError("--legibility: draws its own fields (no SCENE, --dataset, --method, "
                        "--budgets or --transfer-edit)");
    }
    bench::BenchOptions options;
    std::vector<double> budgets;
    if (isScene) {
        if (arguments.datasetGiven || arguments.methodGiven) {
            throw DataError("--dataset/--method: a SCENE is measured with its own volumes and "
                            "splat nodes, at --budgets");
        }
        budgets = parseBudgets(arguments.budgets);
        checkSceneOptions(arguments.framing, BudgetOverride{});
    } else if (arguments.transferEdit > 0) {
        throw DataError("--transfer-edit: only with a SCENE (its transfer functions are edited)");
    } else {
        const Framing& framing = arguments.framing;
        if (arguments.budgetsGiven || !framing.direction.empty() || !framing.azimuth.empty() ||
            !framing.elevation.empty() || !framing.zoom.empty()) {
            throw DataError("--budgets/--direction/--azimuth/--elevation/--zoom: only with a "
                            "SCENE (the datasets have their own views; --method sets budgets)");
        }
        options.datasets = withOption(
            "--dataset", [&] { return bench::BenchDataset::parseList(arguments.datasets); });
        options.camera = parseFramingCamera(framing.camera);
        options.methods =
            withOption("--method", [&] { return bench::BenchMethod::parseList(arguments.methods); });
    }
    options.sizes = parseSizes(arguments.sizes);
    for (const bench::BenchMethod& method : options.methods) {
        for (const bench::BenchDataset& dataset : options.datasets) {
            if (method.needsVectors() && dataset.source() != bench::BenchDataset::Source::Tornado) {
                throw Error("--method: " + method.name() + " draws vectors, but dataset " +
                            dataset.name() + " is scalar (use tornado<N>)");
            }
        }
    }
    options.repeat = arguments.repeat;
    options.warmup = arguments.warmup;
    options.threads = arguments.threads;
    options.reference = !arguments.noReference;
    // The outputs before the long run.
    if (!arguments.csv.empty()) {
        requireFileExtension(arguments.csv, {".csv"}, "CSV");
        requireWritableFile(arguments.csv, "the CSV file");
    }
    if (!arguments.plot.empty()) {
        requireFileExtension(arguments.plot, {".svg"}, "plot");
        requireWritableFile(arguments.plot, "the plot");
    }
    return {options, budgets, memoryLimitOf(arguments.memoryLimit)};
}

// `bench SCENE --transfer-edit N`: the frames after transfer-function edits, on the CPU.
void runTransferEditBench(const BenchArguments& arguments) {
    const glm::ivec2 size = parseSizes(arguments.sizes).front();
    if (!arguments.images.empty()) {
        requireWritableFile(bench::transferEditImagePath(arguments.images, "exact"), "the images");
    }
    const std::vector<bench::TransferEditTime> rows = bench::measureTransferEdit(
        sceneToMeasure(arguments), size,
        {0, static_cast<std::uint64_t>(arguments.transferEdit)}, arguments.threads,
        arguments.images);
    std::printf("texsplat bench --transfer-edit: %s, %dx%d, %s; wall time of the frame after "
                "the edit (loading not counted)\n",
                arguments.scene.c_str(), size.x, size.y,
                render::cpu::CpuRenderer(arguments.threads).description().c_str());
    std::printf("%s", bench::transferEditTable(rows).c_str());
}

// The backends of a comma-separated list, each once in the order given (auto resolves as
// `render` does), and the GL context when one of them is GL.
std::pair<std::vector<render::Backend>, std::shared_ptr<gl::EglContext>>
resolveBackends(const std::string& names) {
    std::vector<render::Backend> backends;
    std::shared_ptr<gl::EglContext> context;
    for (const std::string& name : splitList(names)) {
        render::BackendChoice choice =
            render::BackendChoice::resolve(render::parseBackendRequest(name));
        if (std::find(backends.begin(), backends.end(), choice.backend) != backends.end()) {
            continue;
        }
        backends.push_back(choice.backend);
        if (choice.context && !context) {
            context = choice.context;
        }
    }
    if (backends.empty()) {
        throw DataError("--backend: expected cpu, gl or auto (or a list, e.g. cpu,gl), got ''");
    }
    return {backends, context};
}

// `bench --legibility`: how well vector marks show known flows, per zoom, beside a line integral
// convolution of the same flow.
void runLegibilityBench(const BenchArguments& arguments) {
    const auto [backends, context] = resolveBackends(arguments.backends);
    if (!arguments.images.empty()) {
        std::filesystem::create_directories(arguments.images);
    }
    std::vector<bench::LegibilityResult> rows;
    std::fprintf(stderr, "%s", bench::legibilityTableHeader().c_str());
    for (const bench::LegibilityCase& what : bench::legibilityCases(backends)) {
        bench::LegibilityOptions options;
        options.repeat = arguments.repeat;
        if (!arguments.images.empty()) {
            options.imagePath = arguments.images + "/" + bench::legibilityImageName(what);
        }
        rows.push_back(bench::measureLegibility(what, options));
        std::fprintf(stderr, "%s", bench::legibilityTableRow(rows.back()).c_str());
    }
    std::printf("texsplat bench --legibility: median and 90th percentile of the angle between the "
                "image's streaks (structure tensor of central differences, smoothed over half a "
                "voxel) and the flow, beside a line integral convolution of the same flow; skew "
                "> 0: the marks point downstream; frame: median of %d\n",
                arguments.repeat);
    std::printf("%s", bench::legibilityTable(rows).c_str());
}

void runBench(const BenchArguments& arguments, CheckedBench checked) {
    setMemoryLimit(checked.memoryLimit);
    const ThreadLimit threadLimit(arguments.threads);
    if (arguments.transferEdit > 0) {
        runTransferEditBench(arguments);
        return;
    }
    if (arguments.legibility) {
        runLegibilityBench(arguments);
        return;
    }
    const bool isScene = !arguments.scene.empty();
    bench::BenchOptions& options = checked.options;
    const std::vector<double>& budgets = checked.budgets;
    // A scene is measured on the CPU: unless asked otherwise, not on the GL device auto finds.
    auto [backends, context] =
        resolveBackends(isScene && !arguments.backendGiven ? "cpu" : arguments.backends);
    options.backends = backends;
    options.cpuThreads = arguments.threads;
    const std::string devices = deviceSummary(options, context.get());
    bench::BenchRunner runner(options);
    auto progress = std::make_shared<ProgressPrinter>();
    runner.setProgress([progress](const std::string& stage, double fraction) {
        (*progress)(stage, fraction);
    });
    const std::vector<bench::BenchResult> results =
        isScene ? runner.runScene(*sceneToMeasure(arguments),
                                  std::filesystem::path(arguments.scene).filename().string(),
                                  budgets)
                : runner.run();

    const unsigned cores = std::thread::hardware_concurrency();
    const char* camera =
        isScene ? "the scene's camera"
        : options.camera == render::FramingCamera::Orthographic ? "orthographic camera"
                                                                 : "perspective camera";
    std::printf("texsplat bench: %s, %u CPU threads, %s; median of %d frames after %d warm-up\n",
                devices.c_str(), cores, camera, arguments.repeat, arguments.warmup);
    std::printf("%s", bench::benchTable(results).c_str());
    std::printf("frame/c, draw/c: frame and draw time over the fill-rate ceiling (same quads, "
                "trivial shader, same blending; GL); fragments: GL_SAMPLES_PASSED; errors: RGB "
                "of premultiplied floats, PSNR peak 1; frame/tex: frame time over the "
                "full-quality texture splats' on the same backend; vs gl: frame time over the "
                "same method's on GL\n");
    if (!arguments.csv.empty()) {
        bench::writeBenchCsv(results, arguments.csv);
    }
    if (!arguments.plot.empty()) {
        bench::writeBenchPlot(results,
                              "texsplat bench: error against frame time (" + devices + ", " +
                                  std::to_string(cores) + " threads)",
                              arguments.plot);
    }
}

} // namespace

void addBenchCommand(CLI::App& app, int& exitCode, CommandMode mode) {
    auto arguments = std::make_shared<BenchArguments>();
    CLI::App* command = app.add_subcommand(
        "bench", "Time texture splats, textured and polygonal Gaussians against the GL device's "
                 "fill-rate ceiling and their error against the ray-cast reference; or a "
                 "SCENE's own splat nodes at a range of octree budgets");
    command
        ->add_option("--dataset", arguments->datasets,
                     "Comma-separated datasets: ml<N>, tornado<N>, blob<N> (N samples per axis), "
                     "e.g. ml41,ml128,tornado128,blob256")
        ->capture_default_str();
    command->add_option("--size", arguments->sizes, "Comma-separated image sizes WxH")
        ->capture_default_str();
    command
        ->add_option("--method", arguments->methods,
                     "Comma-separated methods: texture, texture-gaussian, polygon, vector and "
                     "combined (tornado datasets only); @FRACTION draws the octree cut of that "
                     "fraction of the splats")
        ->capture_default_str();
    command->add_option("--repeat", arguments->repeat, "Timed frames per method (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    command->add_option("--warmup", arguments->warmup, "Untimed frames first")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    command->add_option("--threads", arguments->threads,
                        "Threads of the ray caster and the CPU backend (0: all cores)")
        ->check(CLI::Range(0, 1024));
    command
        ->add_option("--backend", arguments->backends,
                     "Comma-separated backends each method runs on: cpu, gl, auto (as render "
                     "picks), e.g. cpu,gl to compare them in one run")
        ->capture_default_str();
    command->add_flag("--no-reference", arguments->noReference,
                      "Skip the ray-cast reference (no error against it)");
    command->add_option("--csv", arguments->csv, "Also write the results as CSV to this file");
    command->add_option("--plot", arguments->plot,
                        "Also write a plot of error against frame time (SVG) to this file");
    addMemoryLimitOption(*command, arguments->memoryLimit);
    command->add_option("scene", arguments->scene,
                        "A scene file (.iv) to measure instead of the datasets: its splat nodes "
                        "at each of --budgets, error against its full-resolution image and the "
                        "ray-cast reference (its camera, or one framing it as render does)")
        ->type_name("SCENE");
    command
        ->add_option("--budgets", arguments->budgets,
                     "With a SCENE: comma-separated fractions in (0, 1] of each splat node's "
                     "full-resolution splats, set as its maxSplats (1: full resolution)")
        ->capture_default_str();
    command
        ->add_option("--transfer-edit", arguments->transferEdit,
                     "With a SCENE: time the frame after two edits of its transfer functions "
                     "(opacities halved; the lower 30 % of the range hidden), at full resolution "
                     "and at this many splats, against re-classifying the whole grid as before "
                     "value ranges (CPU backend)")
        ->check(CLI::Range(1, 2000000000))
        ->type_name("SPLATS");
    command
        ->add_option("--images", arguments->images,
                     "With --transfer-edit: write the exact frame and the interactive preview "
                     "after each edit into this folder as PNGs, for a look; with --legibility, "
                     "each case's image")
        ->type_name("FOLDER");
    command->add_flag("--legibility", arguments->legibility,
                      "Measure how well vector marks show known flows (a vortex, a saddle, "
                      "uniform fields) at 4 to 16 pixels per voxel, beside a line integral "
                      "convolution of the same flow");
    addViewOptions(*command, arguments->framing);
    command->callback([arguments, command, mode, &exitCode] {
        arguments->datasetGiven = command->count("--dataset") > 0;
        arguments->methodGiven = command->count("--method") > 0;
        arguments->backendGiven = command->count("--backend") > 0;
        arguments->budgetsGiven = command->count("--budgets") > 0;
        CheckedBench checked = checkBenchOptions(*arguments);
        if (mode == CommandMode::Run) {
            runBench(*arguments, std::move(checked));
        }
        exitCode = kExitOk;
    });
}

} // namespace texsplat::apps
