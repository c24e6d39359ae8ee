#include "nodes/kernel/KernelPlot.h"

#include "scenegraph/AtomicFile.h"
#include "scenegraph/FileExtension.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace texsplat::kernel {

namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 400;
constexpr int kMargin = 50;
constexpr int kSamples = 400;

} // namespace

std::string kernelPlotSvg(const RadialKernel& kernel) {
    const double rMax = 1.05 * kernel.support();
    double yMax = 0.0;
    for (int i = 0; i <= kSamples; ++i) {
        const double r = rMax * i / kSamples;
        yMax = std::max({yMax, kernel.value(r), kernel.footprint(r)});
    }
    yMax = std::ceil(yMax * 10.0) / 10.0;
    const double plotWidth = kWidth - 2 * kMargin;
    const double plotHeight = kHeight - 2 * kMargin;
    const auto x = [&](double r) { return kMargin + r / rMax * plotWidth; };
    const auto y = [&](double value) { return kHeight - kMargin - value / yMax * plotHeight; };
    std::ostringstream svg;
    svg.precision(5);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\""
        << kHeight << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << kMargin << "\" y=\"20\">" << kernel.description() << "</text>\n";
    svg << "<path d=\"M" << x(0) << "," << y(0) << " H" << x(rMax) << " M" << x(0) << "," << y(0)
        << " V" << y(yMax) << "\" stroke=\"black\" fill=\"none\"/>\n";
    for (int tick = 0; tick <= static_cast<int>(rMax / 0.25); ++tick) {
        const double r = 0.25 * tick;
        svg << "<text x=\"" << x(r) << "\" y=\"" << y(0) + 16 << "\" text-anchor=\"middle\">" << r
            << "</text>\n";
    }
    for (int tick = 0; tick <= static_cast<int>(std::round(yMax / 0.1)); ++tick) {
        const double value = 0.1 * tick;
        svg << "<text x=\"" << kMargin - 6 << "\" y=\"" << y(value) + 4
            << "\" text-anchor=\"end\">" << value << "</text>\n";
    }
    svg << "<text x=\"" << x(rMax) << "\" y=\"" << y(0) + 32 << "\" text-anchor=\"end\">r (voxels)"
        << "</text>\n";
    const auto curve = [&](auto function, const char* color, const char* label, int row) {
        svg << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.5\" points=\"";
        for (int i = 0; i <= kSamples; ++i) {
            const double r = rMax * i / kSamples;
            svg << x(r) << "," << y(function(r)) << " ";
        }
        svg << "\"/>\n<text x=\"" << kWidth - kMargin - 120 << "\" y=\"" << kMargin + 16 * row
            << "\" fill=\"" << color << "\">" << label << "</text>\n";
    };
    curve([&](double r) { return kernel.value(r); }, "#1f5fbf", "g(r) kernel", 0);
    curve([&](double r) { return kernel.footprint(r); }, "#bf3f1f", "f(r) footprint", 1);
    svg << "</svg>\n";
    return svg.str();
}

void writeKernelPlot(const RadialKernel& kernel, const std::string& path) {
    requireFileExtension(path, {".svg"}, "plot");
    writeFileAtomically(path, kernelPlotSvg(kernel));
}

} // namespace texsplat::kernel
