#include "apps/Commands.h"
#include "apps/MemoryLimitOption.h"

#include "nodes/image/ImageComparison.h"
#include "nodes/image/ImageIo.h"
#include "scenegraph/AtomicFile.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/MemoryLimit.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace texsplat::apps {
namespace {

using image::ImageComparison;

struct CompareArguments {
    std::string reference;
    std::string test;
    std::string diff;
    double diffScale = 0.0;
    double peak = 1.0;
    std::string region;
    std::string memoryLimit;
    bool json = false;
};

constexpr const char* kChannelNames[] = {"R", "G", "B", "A"};

/// A number as JSON has it: 9 significant digits, and null for the infinite PSNR of identical
/// images (JSON has no infinity).
std::string jsonNumber(double value) {
    if (!std::isfinite(value))
        return "null";
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string jsonString(const std::string& value) {
    std::string quoted = "\"";
    for (const char c : value) {
        if (c == '"' || c == '\\') {
            quoted += '\\';
            quoted += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            quoted += escape;
        } else {
            quoted += c;
        }
    }
    return quoted + "\"";
}

std::string jsonError(const ImageComparison::ChannelError& error, bool withChannel) {
    std::string text = "{\"rmse\": " + jsonNumber(error.rmse) +
                       ", \"psnr\": " + jsonNumber(error.psnr) +
                       ", \"maxAbsError\": " + jsonNumber(error.maxAbsError) + ", \"maxAt\": [" +
                       std::to_string(error.maxX) + ", " + std::to_string(error.maxY) + "]";
    if (withChannel)
        text += std::string(", \"maxChannel\": \"") + kChannelNames[error.maxChannel] + "\"";
    return text + "}";
}

void printJson(const CompareArguments& arguments, const image::Image& reference,
               const image::ImageRegion& region, const ImageComparison& comparison,
               double diffScale) {
    std::string text = "{\n";
    text += "  \"reference\": " + jsonString(arguments.reference) + ",\n";
    text += "  \"test\": " + jsonString(arguments.test) + ",\n";
    text += "  \"width\": " + std::to_string(reference.width()) + ",\n";
    text += "  \"height\": " + std::to_string(reference.height()) + ",\n";
    text += "  \"region\": [" + std::to_string(region.x) + ", " + std::to_string(region.y) +
            ", " + std::to_string(region.width) + ", " + std::to_string(region.height) + "],\n";
    text += "  \"peak\": " + jsonNumber(comparison.peak()) + ",\n";
    text += "  \"comparedPixels\": " + std::to_string(comparison.comparedPixels()) + ",\n";
    text += "  \"nonFinitePixels\": " + std::to_string(comparison.nonFinitePixels()) + ",\n";
    text += "  \"channels\": {\n";
    for (int c = 0; c < 4; ++c)
        text += std::string("    \"") + kChannelNames[c] +
                "\": " + jsonError(comparison.channel(c), false) + ",\n";
    text += "    \"RGB\": " + jsonError(comparison.rgb(), true) + "\n  }";
    if (!arguments.diff.empty())
        text += ",\n  \"diff\": {\"path\": " + jsonString(arguments.diff) +
                ", \"scale\": " + jsonNumber(diffScale) + "}";
    std::printf("%s\n}\n", text.c_str());
}

void printErrorRow(const char* name, const ImageComparison::ChannelError& error) {
    std::printf("%-7s  %-12.6e  %9.3f  %-13.6e  (%d, %d)", name, error.rmse, error.psnr,
                error.maxAbsError, error.maxX, error.maxY);
}

void printText(const CompareArguments& arguments, const image::Image& reference,
               const image::ImageRegion& region, const ImageComparison& comparison,
               double diffScale) {
    std::printf("reference  %s (%s)\n", arguments.reference.c_str(),
                reference.sizeString().c_str());
    std::printf("test       %s\n", arguments.test.c_str());
    std::printf("compared   %zu pixels in region %d,%d %dx%d; %zu non-finite left out; "
                "PSNR peak %g\n",
                comparison.comparedPixels(), region.x, region.y, region.width, region.height,
                comparison.nonFinitePixels(), comparison.peak());
    std::printf("channel  rmse          psnr [dB]  max abs error  at (x, y)\n");
    for (int c = 0; c < 4; ++c) {
        printErrorRow(kChannelNames[c], comparison.channel(c));
        std::printf("\n");
    }
    printErrorRow("RGB", comparison.rgb());
    std::printf(" in %s\n", kChannelNames[comparison.rgb().maxChannel]);
    if (!arguments.diff.empty())
        std::printf("diff       %s (viridis from 0 to %g)\n", arguments.diff.c_str(), diffScale);
}

/// Parses "X,Y,WIDTH,HEIGHT" (four integers, nothing else).
bool parseRegion(const std::string& text, image::ImageRegion& region) {
    int consumed = 0;
    return std::sscanf(text.c_str(), "%d,%d,%d,%d%n", &region.x, &region.y, &region.width,
                       &region.height, &consumed) == 4 &&
           static_cast<std::size_t>(consumed) == text.size();
}

image::ImageRegion regionOf(const CompareArguments& arguments, const image::Image& reference) {
    image::ImageRegion region = reference.bounds();
    if (!arguments.region.empty())
        parseRegion(arguments.region, region); // validated when the command line was parsed
    return region;
}

/// Compares the two images; a DataError (sizes, region) names the test file as where.
ImageComparison compareFiles(const CompareArguments& arguments, const image::Image& reference,
                             const image::Image& test, const image::ComparisonOptions& options) {
    try {
        return ImageComparison(reference, test, options);
    } catch (const DataError& e) {
        throw DataError(arguments.test + ": " + e.what());
    }
}

void runCompare(const CompareArguments& arguments, std::uint64_t memoryLimit) {
    setMemoryLimit(memoryLimit);
    if (!arguments.diff.empty()) {
        // Before the images are decoded, which may take long.
        image::supportedImageFormatOf(arguments.diff);
        requireWritableFile(arguments.diff, "the difference image");
    }
    const image::Image reference = image::readImage(arguments.reference);
    const image::Image test = image::readImage(arguments.test);
    image::ComparisonOptions options;
    options.region = regionOf(arguments, reference);
    options.peak = arguments.peak;
    const ImageComparison comparison = compareFiles(arguments, reference, test, options);
    const double diffScale =
        arguments.diffScale > 0.0 ? arguments.diffScale : comparison.maxPixelError();
    if (!arguments.diff.empty())
        image::writeImage(comparison.differenceImage(diffScale), arguments.diff);
    if (comparison.nonFinitePixels() > 0)
        log(LogLevel::Warning, arguments.test + ": left out " +
                                   std::to_string(comparison.nonFinitePixels()) +
                                   " pixel(s) with NaN or infinite values in one of the images");
    // An opaque image against a transparent one differs in alpha by construction (a PNG over
    // black against an EXR layer, say): say so rather than let the alpha error speak alone.
    const auto isOpaque = [](const image::Image& image) {
        return image.statistics().minimum.a >= 1.0;
    };
    if (isOpaque(reference) != isOpaque(test)) {
        const std::string& opaque = isOpaque(reference) ? arguments.reference : arguments.test;
        const std::string& other = isOpaque(reference) ? arguments.test : arguments.reference;
        log(LogLevel::Warning, opaque + " is opaque (alpha 1 everywhere) and " + other +
                                   " is not: they were composited over different backgrounds; "
                                   "render both with the same --background");
    }
    if (arguments.json)
        printJson(arguments, reference, *options.region, comparison, diffScale);
    else
        printText(arguments, reference, *options.region, comparison, diffScale);
}

} // namespace

void addCompareCommand(CLI::App& app, int& exitCode, CommandMode mode) {
    auto arguments = std::make_shared<CompareArguments>();
    CLI::App* command = app.add_subcommand(
        "compare", "Compare two images: RMSE, PSNR and max abs error per channel and over RGB");
    command->add_option("reference", arguments->reference, "Reference image (.exr or .png)")
        ->required();
    command->add_option("test", arguments->test, "Image to compare against it (.exr or .png)")
        ->required();
    command->add_option("--diff", arguments->diff,
                        "Write the per-pixel RGB error in false color (viridis) to this file");
    command->add_option("--diff-scale", arguments->diffScale,
                        "Error shown at the top of the colormap (default: the largest error)")
        ->check(CLI::NonNegativeNumber);
    command
        ->add_option("--region", arguments->region,
                     "Compare only the rectangle X,Y,WIDTH,HEIGHT (0,0 is the top-left pixel)")
        ->check(CLI::Validator(
            [](std::string& text) {
                image::ImageRegion region;
                return parseRegion(text, region)
                           ? std::string()
                           : "'" + text + "' is not X,Y,WIDTH,HEIGHT (four integers)";
            },
            "X,Y,WIDTH,HEIGHT"));
    command->add_option("--peak", arguments->peak, "Peak value for PSNR (default 1)")
        ->check(CLI::PositiveNumber);
    command->add_flag("--json", arguments->json, "Print the results as JSON");
    addMemoryLimitOption(*command, arguments->memoryLimit);
    command->callback([arguments, mode, &exitCode] {
        const std::uint64_t memoryLimit = memoryLimitOf(arguments->memoryLimit);
        if (mode == CommandMode::Run) {
            runCompare(*arguments, memoryLimit);
        }
        exitCode = kExitOk;
    });
}

} // namespace texsplat::apps
