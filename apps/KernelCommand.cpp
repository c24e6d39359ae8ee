#include "apps/Commands.h"

#include "apps/OptionError.h"
#include "nodes/kernel/CubicKernel.h"
#include "nodes/kernel/FootprintTexture.h"
#include "nodes/kernel/GaussianKernel.h"
#include "nodes/kernel/KernelOptimizer.h"
#include "nodes/kernel/KernelPlot.h"
#include "nodes/kernel/LatticeAnalysis.h"
#include "scenegraph/Error.h"
#include "scenegraph/FileExtension.h"
#include "scenegraph/fields/ValueFormat.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace texsplat::apps {

namespace {

using namespace texsplat::kernel;

// The paper's numbers (Crawfis & Max 1993, section 2) that `texsplat kernel` compares against.
struct PaperNumbers {
    static constexpr double kRelativeRms = 0.00119;
    static constexpr double kMinDeviation = -0.00233;
    static constexpr double kMaxDeviation = 0.00534;
    static constexpr double kLayerMax = 1.00249;
    static constexpr double kLayerMin = 0.99845;
};

struct KernelOptions {
    bool json = false;
    bool optimize = false;
    std::string kernel = "paper";
    std::string start;
    std::optional<double> support;
    std::string spacing;
    std::string texture;
    int resolution = 64;
    double extent = FootprintTexture::kPaperExtent;
    std::string plot;
};

// "a,b,c" → numbers; the option name starts the message of every error, as main prints it.
std::vector<double> parseNumbers(const std::string& text, size_t count, const char* option) {
    std::vector<double> numbers;
    std::istringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        size_t used = 0;
        double value = 0.0;
        try {
            value = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size())
            throw DataError(std::string(option) + ": '" + item + "' is not a number");
        numbers.push_back(value);
    }
    if (numbers.size() != count) {
        std::ostringstream message;
        message << option << ": expected " << count << " comma-separated numbers, got '" << text
                << "'";
        throw DataError(message.str());
    }
    return numbers;
}

// JSON numbers: shortest round-trip form; NaN and infinities (which JSON lacks) become null.
std::string number(double value) {
    return std::isfinite(value) ? sg::formatDouble(value) : "null";
}

template <size_t N> std::string array(const std::array<double, N>& values) {
    std::string text = "[";
    for (size_t i = 0; i < N; ++i)
        text += (i ? ", " : "") + number(values[i]);
    return text + "]";
}

std::string shapeJson(const KernelShape& shape) {
    return "{\"s\": " + number(shape.knot) + ", \"t\": " + number(shape.support) +
           ", \"b\": " + number(shape.b) + ", \"d\": " + number(shape.d) + "}";
}

// The kernel under analysis and how it was made.
struct NamedKernel {
    std::unique_ptr<RadialKernel> kernel;
    LatticeSpacing spacing{1.0, 1.0, 1.0}; ///< lattice spacing in the kernel's coordinates
    std::optional<OptimizerResult> optimization;
};

// The optimizer's settings: on the --spacing lattice (onLattice) or on the cubic one. On a
// non-cubic lattice the support is fixed, to --support or to the paper's t times the largest
// spacing (the sphere around the ellipsoidal kernel's support): with a free support the objective
// keeps falling as t grows, and with the same volume (t times the geometric mean) a 2:1 lattice
// has no interior minimum (docs/kernel.md).
OptimizerOptions optimizerOptions(const KernelOptions& options, bool onLattice) {
    OptimizerOptions settings;
    settings.fixedSupport = options.support;
    if (onLattice && !options.spacing.empty()) {
        const std::vector<double> spacing = parseNumbers(options.spacing, 3, "--spacing");
        settings.spacing = {spacing[0], spacing[1], spacing[2]};
        if (!settings.fixedSupport)
            settings.fixedSupport = CubicKernel::paper().support() *
                                    std::max({spacing[0], spacing[1], spacing[2]});
    }
    return settings;
}

OptimizerResult runOptimizer(const KernelOptions& options, const OptimizerOptions& settings,
                             bool reportProgress) {
    const KernelOptimizer optimizer(settings);
    KernelShape start = optimizer.defaultStart();
    if (!options.start.empty()) {
        const std::vector<double> values = parseNumbers(options.start, 4, "--start");
        start = {values[0], values[1], values[2], values[3]};
    }
    KernelOptimizer::Progress progress;
    if (reportProgress) {
        progress = [](const OptimizerStep& step) {
            std::fprintf(stderr,
                         "texsplat kernel: restart %d iteration %d evaluations %d: s = %.7f "
                         "t = %.7f b = %.7f d = %.7f rms = %.9g\n",
                         step.restart, step.iteration, step.evaluations, step.shape.knot,
                         step.shape.support, step.shape.b, step.shape.d, step.relativeRms);
        };
    }
    return optimizer.optimize(start, progress);
}

// The kernel --kernel names. The paper's kernel under --spacing is the ellipsoidal one, h(x/sx,
// y/sy, z/sz): in voxel coordinates it is the cubic case, so it is analysed on the unit lattice.
NamedKernel makeKernel(const KernelOptions& options) {
    NamedKernel named;
    const OptimizerOptions settings = optimizerOptions(options, true);
    if (options.kernel == "optimized" || options.optimize) {
        named.optimization = runOptimizer(options, settings, options.optimize);
        named.kernel = std::make_unique<CubicKernel>(named.optimization->kernel);
        named.spacing = settings.spacing;
    } else if (options.kernel == "paper") {
        named.kernel = std::make_unique<CubicKernel>(CubicKernel::paper());
    } else {
        const double support = settings.fixedSupport.value_or(CubicKernel::paper().support());
        named.kernel = std::make_unique<GaussianKernel>(
            KernelOptimizer(settings).fitGaussian(support).kernel);
        named.spacing = settings.spacing;
    }
    return named;
}

std::string latticeJson(const Lattice3dStatistics& lattice, const Layer2dStatistics& layer) {
    return "\"lattice3d\": {\"mean\": " + number(lattice.mean) +
           ", \"relative_rms\": " + number(lattice.relativeRms) +
           ", \"min_deviation\": " + number(lattice.minDeviation) +
           ", \"min_at\": " + array(lattice.minAt) +
           ", \"max_deviation\": " + number(lattice.maxDeviation) +
           ", \"max_at\": " + array(lattice.maxAt) + "},\n  \"layer2d\": {\"mean\": " +
           number(layer.mean) + ", \"max\": " + number(layer.max) +
           ", \"max_at\": " + array(layer.maxAt) + ", \"min\": " + number(layer.min) +
           ", \"min_at\": " + array(layer.minAt) + "}";
}

std::string kernelJson(const KernelOptions& options, const NamedKernel& named) {
    const RadialKernel& kernel = *named.kernel;
    const LatticeAnalysis analysis(kernel, named.spacing);
    std::ostringstream json;
    json << "{\n  \"kernel\": \"" << (options.optimize ? "optimized" : options.kernel) << "\",\n"
         << "  \"description\": \"" << kernel.description() << "\",\n"
         << "  \"spacing\": " << array(named.spacing) << ",\n"
         << "  \"t\": " << number(kernel.support()) << ",\n";
    if (const auto* cubic = dynamic_cast<const CubicKernel*>(&kernel)) {
        const CubicCoefficients& k = cubic->coefficients();
        json << "  \"s\": " << number(cubic->knot()) << ",\n  \"coefficients\": {\"p\": ["
             << number(k.a) << ", " << number(k.b) << ", " << number(k.c) << "], \"q\": ["
             << number(k.d) << ", " << number(k.e) << "]},\n";
    } else if (const auto* gaussian = dynamic_cast<const GaussianKernel*>(&kernel)) {
        json << "  \"s\": null,\n  \"coefficients\": null,\n  \"sigma\": "
             << number(gaussian->sigma()) << ",\n  \"amplitude\": "
             << number(gaussian->amplitude()) << ",\n";
    }
    json << "  " << latticeJson(analysis.lattice3d(), analysis.layer2d());
    if (named.optimization) {
        const OptimizerResult& result = *named.optimization;
        json << ",\n  \"optimizer\": {\"shape\": " << shapeJson(result.shape)
             << ", \"relative_rms\": " << number(result.relativeRms)
             << ", \"iterations\": " << result.iterations
             << ", \"evaluations\": " << result.evaluations << ", \"restarts\": " << result.restarts
             << ",\n    \"path\": [";
        for (size_t i = 0; i < result.path.size(); ++i)
            json << (i ? ",\n      " : "\n      ") << "{\"iteration\": " << result.path[i].iteration
                 << ", \"shape\": " << shapeJson(result.path[i].shape)
                 << ", \"relative_rms\": " << number(result.path[i].relativeRms) << "}";
        json << "]}";
    }
    json << "\n}\n";
    return json.str();
}

std::string position(const double* values, size_t count) {
    std::string text = "(";
    for (size_t i = 0; i < count; ++i) {
        char buffer[32];
        std::snprintf(buffer, sizeof(buffer), "%s%.4f", i ? ", " : "", values[i]);
        text += buffer;
    }
    return text + ")";
}

// One row of the table: the paper's value, the printed kernel's and the optimized kernel's
// measured values, and each one's difference from the paper.
void printRow(const char* name, double paper, double printed, double optimized) {
    std::printf("%-24s %12.7g %12.7g %10.2e %12.7g %10.2e\n", name, paper, printed,
                printed - paper, optimized, optimized - paper);
}

void printLocation(const char* name, const char* paper, const std::string& printed,
                   const std::string& optimized) {
    std::printf("%-24s %12s %23s %23s\n", name, paper, printed.c_str(), optimized.c_str());
}

void printTable(const KernelOptions& options, const OptimizerResult& optimized) {
    const CubicKernel paper = CubicKernel::paper();
    const LatticeAnalysis printedAnalysis(paper);
    const LatticeAnalysis optimizedAnalysis(optimized.kernel);
    const Lattice3dStatistics p3 = printedAnalysis.lattice3d();
    const Lattice3dStatistics o3 = optimizedAnalysis.lattice3d();
    const Layer2dStatistics p2 = printedAnalysis.layer2d();
    const Layer2dStatistics o2 = optimizedAnalysis.layer2d();
    const CubicCoefficients& pk = paper.coefficients();
    const CubicCoefficients& ok = optimized.kernel.coefficients();
    std::printf("Crawfis & Max (1993), section 2: the paper's numbers, the printed kernel as "
                "measured here, and the kernel this project's optimizer finds\n");
    std::printf("%-24s %12s %12s %10s %12s %10s\n", "quantity", "paper", "printed g", "diff",
                "optimized", "diff");
    printRow("support t", paper.support(), paper.support(), optimized.kernel.support());
    printRow("knot s", paper.knot(), paper.knot(), optimized.kernel.knot());
    printRow("p: a", pk.a, pk.a, ok.a);
    printRow("p: b (r^2)", pk.b, pk.b, ok.b);
    printRow("p: c (r^3)", pk.c, pk.c, ok.c);
    printRow("q: d ((t-r)^2)", pk.d, pk.d, ok.d);
    printRow("q: e ((t-r)^3)", pk.e, pk.e, ok.e);
    printRow("3D relative r.m.s.", PaperNumbers::kRelativeRms, p3.relativeRms, o3.relativeRms);
    printRow("3D min deviation", PaperNumbers::kMinDeviation, p3.minDeviation, o3.minDeviation);
    printLocation("  at (x, y, z)", "(.26,.26,.26)", position(p3.minAt.data(), 3),
                  position(o3.minAt.data(), 3));
    printRow("3D max deviation", PaperNumbers::kMaxDeviation, p3.maxDeviation, o3.maxDeviation);
    printLocation("  at (x, y, z)", "(.5,.5,0)", position(p3.maxAt.data(), 3),
                  position(o3.maxAt.data(), 3));
    printRow("2D layer max", PaperNumbers::kLayerMax, p2.max, o2.max);
    printLocation("  at (x, y)", "(.5,.5)", position(p2.maxAt.data(), 2),
                  position(o2.maxAt.data(), 2));
    printRow("2D layer min", PaperNumbers::kLayerMin, p2.min, o2.min);
    printLocation("  at (x, y)", "(.25,.25)", position(p2.minAt.data(), 2),
                  position(o2.minAt.data(), 2));
    const GaussianFit gaussian =
        KernelOptimizer().fitGaussian(options.support.value_or(paper.support()));
    const LatticeAnalysis gaussianAnalysis(gaussian.kernel);
    const Lattice3dStatistics g3 = gaussianAnalysis.lattice3d();
    const Layer2dStatistics g2 = gaussianAnalysis.layer2d();
    std::printf("\nGaussian of the same extent (%s, best sigma for the lattice):\n"
                "  3D relative r.m.s. %.5g, deviations %.5g .. %.5g; 2D layer %.5f .. %.5f\n",
                gaussian.kernel.description().c_str(), g3.relativeRms, g3.minDeviation,
                g3.maxDeviation, g2.min, g2.max);
}

// Item 7 of the kernel issue: the two answers for a non-cubic lattice, side by side.
void printAnisotropic(const KernelOptions& options, const OptimizerResult& optimized) {
    const LatticeSpacing spacing = optimizerOptions(options, true).spacing;
    const CubicKernel paper = CubicKernel::paper();
    const Lattice3dStatistics scaled = LatticeAnalysis(paper).lattice3d();
    const LatticeAnalysis isotropic(optimized.kernel, spacing);
    const Lattice3dStatistics radial = isotropic.lattice3d();
    const Layer2dStatistics radialLayer = isotropic.layer2d();
    std::printf("\nanisotropic spacing (%g, %g, %g):\n", spacing[0], spacing[1], spacing[2]);
    std::printf("  (a) paper kernel scaled by the spacing (ellipsoidal; footprint is a "
                "view-dependent ellipse):\n      3D relative r.m.s. %.5g, deviations %.5g .. "
                "%.5g (the cubic lattice's, exactly)\n",
                scaled.relativeRms, scaled.minDeviation, scaled.maxDeviation);
    std::printf("  (b) rotationally symmetric kernel optimized for this lattice (%s; one "
                "circular footprint):\n      3D relative r.m.s. %.5g, deviations %.5g .. %.5g; "
                "2D layer along z relative to its mean %.5f .. %.5f\n",
                optimized.kernel.description().c_str(), radial.relativeRms, radial.minDeviation,
                radial.maxDeviation, radialLayer.min / radialLayer.mean,
                radialLayer.max / radialLayer.mean);
}

void printOptimization(const OptimizerResult& result, double seconds) {
    std::printf("optimizer path (best point after each group of iterations):\n");
    std::printf("%8s %8s %12s %12s %12s %12s %14s\n", "restart", "iter", "s", "t", "b", "d",
                "relative rms");
    for (const OptimizerStep& step : result.path)
        std::printf("%8d %8d %12.8f %12.8f %12.8f %12.8f %14.9g\n", step.restart, step.iteration,
                    step.shape.knot, step.shape.support, step.shape.b, step.shape.d,
                    step.relativeRms);
    const CubicCoefficients& k = result.kernel.coefficients();
    std::printf("result: t = %.7f, s = %.7f, relative r.m.s. %.9g after %d iterations, %d "
                "evaluations, %d restarts, %.2f s\n",
                result.kernel.support(), result.kernel.knot(), result.relativeRms,
                result.iterations, result.evaluations, result.restarts, seconds);
    std::printf("normalized: g(r) = %.6f %+.6f r^2 %+.6f r^3 ; %.6f (t-r)^2 %+.6f (t-r)^3\n", k.a,
                k.b, k.c, k.d, k.e);
}

// Writes the texture and plot the options ask for; returns the texture's summary line (empty
// without --texture) for the caller to print after the results. Runs before any result is
// printed, so that a kernel the texture cannot hold or an unwritable path fails with no output.
std::string writeOutputs(const KernelOptions& options, const RadialKernel& kernel) {
    std::string summary;
    if (!options.texture.empty()) {
        const FootprintTexture texture(kernel, options.resolution, options.extent);
        const TextureRipple ripple = texture.measureLayerRipple(kernel);
        const TextureRipple ripple8 = texture.quantizedTo8Bits().measureLayerRipple(kernel);
        texture.write(options.texture);
        char numbers[400]; // the path is appended separately: it may be of any length
        std::snprintf(numbers, sizeof numbers,
                      ": %dx%d texels over [-%g, %g]^2; 2D layer sum %.6f .. %.6f (exact %.6f .. "
                      "%.6f), texture adds up to %.3g; as 8-bit texels up to %.3g\n",
                      options.resolution, options.resolution, options.extent, options.extent,
                      ripple.min, ripple.max, ripple.exactMin, ripple.exactMax, ripple.maxError,
                      ripple8.maxError);
        summary = "texture " + options.texture + numbers;
    }
    if (!options.plot.empty())
        writeKernelPlot(kernel, options.plot);
    return summary;
}

// What the libraries would reject, checked before any work (the optimizer, output) and named by
// its option. --support is checked on each lattice it is used on: the table's optimizer runs on
// the cubic lattice even with --spacing.
void checkOptions(const KernelOptions& options) {
    if (options.support && options.json && !options.optimize && options.kernel == "paper")
        throw DataError("--support: needs --kernel optimized|gaussian or --optimize with --json "
                        "(the paper's kernel has its own support)");
    const OptimizerOptions onLattice = optimizerOptions(options, true);
    withOption("--spacing", [&] { LatticeAnalysis::checkSpacing(onLattice.spacing); });
    if (options.support) {
        withOption("--support", [&] { KernelOptimizer{onLattice}; });
        if (!options.json && !options.optimize)
            withOption("--support", [&] { KernelOptimizer{optimizerOptions(options, false)}; });
    }
    withOption("--extent", [&] { FootprintTexture::checkExtent(options.extent); });
    if (!options.texture.empty())
        FootprintTexture::checkPath(options.texture);
    if (!options.plot.empty())
        requireFileExtension(options.plot, {".svg"}, "plot");
}

// Writes the kernel's outputs after checkOptions().
void runKernelCommand(const KernelOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    const NamedKernel named = makeKernel(options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const std::string textureSummary = writeOutputs(options, *named.kernel);
    if (options.json) {
        std::fputs(kernelJson(options, named).c_str(), stdout);
    } else if (options.optimize) {
        printOptimization(*named.optimization, seconds);
    } else {
        const bool cubic = options.spacing.empty();
        const OptimizerResult optimized =
            named.optimization && cubic
                ? *named.optimization
                : runOptimizer(options, optimizerOptions(options, false), false);
        printTable(options, optimized);
        if (!cubic)
            printAnisotropic(options, named.optimization
                                          ? *named.optimization
                                          : runOptimizer(options, optimizerOptions(options, true),
                                                         false));
    }
    std::fputs(textureSummary.c_str(), options.json ? stderr : stdout);
}

} // namespace

void addKernelCommand(CLI::App& app, int& exitCode, CommandMode mode) {
    auto options = std::make_shared<KernelOptions>();
    CLI::App* command = app.add_subcommand(
        "kernel", "The reconstruction kernel (Crawfis & Max 1993): the paper's table, the "
                  "optimizer, footprint textures and plots");
    command->add_flag("--json", options->json, "Print one JSON object for the chosen kernel");
    command->add_option("--kernel", options->kernel, "Kernel to analyse (default paper)")
        ->check(CLI::IsMember({"paper", "optimized", "gaussian"}));
    command->add_flag("--optimize", options->optimize,
                      "Run the optimizer; print its path (progress on stderr) and result");
    command->add_option("--start", options->start,
                        "Optimizer start s,t,b,d (a = 1; default 0.9,1.55,-2,0.12)");
    command->add_option(
        "--support", options->support,
        "Optimize for this fixed support t: more than half the cell diagonal, at most " +
            number(LatticeAnalysis::kMaxSupportInCellSizes) +
            " times the cube root of the cell volume");
    command->add_option("--spacing", options->spacing,
                        "Voxel spacing sx,sy,sz of a non-cubic lattice, the largest at most " +
                            number(LatticeAnalysis::kMaxSpacingRatio) + " times the smallest");
    command->add_option("--texture", options->texture,
                        "Write the footprint texture f: .pfm (float gray), .exr (float RGBA, "
                        "each channel f) or .png (8-bit, white with alpha f)");
    command
        ->add_option("--resolution", options->resolution,
                     "Texture size N of the footprint texture (default 64)")
        ->check(CLI::Range(2, 8192));
    command->add_option("--extent", options->extent,
                        "Texture half-width in voxels, at most " +
                            number(FootprintTexture::kMaxExtent) +
                            " (default 1.6, the paper's extent)");
    command->add_option("--plot", options->plot, "Write g(r) and f(r) to this .svg file");
    command->callback([options, mode, &exitCode] {
        checkOptions(*options);
        if (mode == CommandMode::Run) {
            runKernelCommand(*options);
        }
        exitCode = kExitOk;
    });
}

} // namespace texsplat::apps
