#include "nodes/bench/BenchReport.h"

#include "scenegraph/AtomicFile.h"
#include "scenegraph/FileExtension.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace texsplat::bench {
namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// A measured number for the table: "-" when not measured, "inf" for an infinite PSNR.
std::string cell(const char* pattern, double value) {
    if (std::isnan(value)) {
        return "-";
    }
    if (std::isinf(value)) {
        return value > 0 ? "inf" : "-inf";
    }
    return format(pattern, value);
}

// A number for CSV: empty when not measured, 9 significant digits.
std::string csvNumber(double value) {
    if (std::isnan(value)) {
        return "";
    }
    if (std::isinf(value)) {
        return value > 0 ? "inf" : "-inf";
    }
    return format("%.9g", value);
}

std::string sizeText(const BenchResult& result) {
    return std::to_string(result.width) + "x" + std::to_string(result.height);
}

double phaseMs(const BenchResult& result, sg::RenderPhase phase) {
    return 1e3 * result.phaseSeconds[static_cast<std::size_t>(phase)];
}

std::string escapeXml(const std::string& text) {
    std::string escaped;
    for (const char c : text) {
        switch (c) {
        case '&': escaped += "&amp;"; break;
        case '<': escaped += "&lt;"; break;
        case '>': escaped += "&gt;"; break;
        case '"': escaped += "&quot;"; break;
        default: escaped += c;
        }
    }
    return escaped;
}

constexpr int kWidth = 760;
constexpr int kHeight = 480;
constexpr int kLeft = 80;
constexpr int kRight = 200;
constexpr int kTop = 40;
constexpr int kBottom = 60;
constexpr const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                   "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

// A decade range [10^lo, 10^hi] that holds every value (positive, finite) with a margin.
void decadeRange(const std::vector<double>& values, double& lo, double& hi) {
    double minimum = std::numeric_limits<double>::infinity();
    double maximum = 0.0;
    for (const double value : values) {
        minimum = std::min(minimum, value);
        maximum = std::max(maximum, value);
    }
    if (values.empty()) {
        minimum = 1.0;
        maximum = 10.0;
    }
    lo = std::floor(std::log10(minimum) - 0.05);
    hi = std::ceil(std::log10(maximum) + 0.05);
    if (hi <= lo) {
        hi = lo + 1.0;
    }
}

std::string marker(const std::string& method, double x, double y, const char* color) {
    std::ostringstream svg;
    const bool hollow = method.find('@') != std::string::npos;
    const std::string paint = hollow ? std::string("fill=\"white\" stroke=\"") + color +
                                           "\" stroke-width=\"1.5\""
                                     : std::string("fill=\"") + color + "\"";
    if (method.rfind("texture-gaussian", 0) == 0) {
        svg << "<rect x=\"" << x - 4.5 << "\" y=\"" << y - 4.5 << "\" width=\"9\" height=\"9\" "
            << paint << "/>";
    } else if (method.rfind("polygon", 0) == 0) {
        svg << "<path d=\"M" << x << "," << y - 6 << " L" << x + 5.5 << "," << y + 4 << " L"
            << x - 5.5 << "," << y + 4 << " Z\" " << paint << "/>";
    } else {
        svg << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" " << paint << "/>";
    }
    return svg.str();
}

} // namespace

std::string benchTable(const std::vector<BenchResult>& results) {
    std::string text;
    char line[512];
    std::snprintf(line, sizeof line,
                  "%-11s %-9s %-18s %-7s %9s %11s %11s %9s %9s %9s %7s %7s %10s %8s %10s %8s "
                  "%9s %7s\n",
                  "dataset", "size", "method", "backend", "splats", "fragments", "ceil frags",
                  "frame ms", "draw ms", "ceil ms", "frame/c", "draw/c", "ref RMSE", "ref PSNR",
                  "full RMSE", "full PSNR", "frame/tex", "vs gl");
    text += line;
    for (const BenchResult& r : results) {
        const bool counted = r.backend == "gl"; // fragments and the ceiling are GL's
        std::snprintf(
            line, sizeof line,
            "%-11s %-9s %-18s %-7s %9zu %11s %11s %9.2f %9.2f %9s %7s %7s %10s %8s %10s %8s %9s "
            "%7s\n",
            r.dataset.c_str(), sizeText(r).c_str(), r.method.c_str(), r.backend.c_str(), r.splats,
            counted ? std::to_string(r.fragments).c_str() : "-",
            counted ? std::to_string(r.ceilingFragments).c_str() : "-", 1e3 * r.frameSeconds,
            1e3 * r.drawSeconds(), cell("%.2f", 1e3 * r.ceilingSeconds).c_str(),
            cell("%.3f", r.frameRatio).c_str(), cell("%.3f", r.drawRatio).c_str(),
            cell("%.3e", r.referenceRmse).c_str(), cell("%.2f", r.referencePsnr).c_str(),
            cell("%.3e", r.fullRmse).c_str(), cell("%.2f", r.fullPsnr).c_str(),
            cell("%.3f", r.fullFrameRatio).c_str(), cell("%.4f", r.glFrameRatio).c_str());
        text += line;
    }
    return text;
}

std::string benchCsv(const std::vector<BenchResult>& results) {
    std::string text = "dataset,width,height,method,full_quality,splats,fragments,"
                       "ceiling_fragments,frame_ms,load_ms,classify_ms,order_ms,upload_ms,"
                       "draw_ms,read_back_ms,ceiling_ms,frame_ratio,draw_ratio,reference_rmse,"
                       "reference_psnr,full_rmse,full_psnr,full_frame_ratio,backend,gl_frame_ratio\n";
    for (const BenchResult& r : results) {
        text += r.dataset + "," + std::to_string(r.width) + "," + std::to_string(r.height) + "," +
                r.method + "," + (r.isFullQuality ? "1" : "0") + "," + std::to_string(r.splats) +
                "," + std::to_string(r.fragments) + "," + std::to_string(r.ceilingFragments) +
                "," + csvNumber(1e3 * r.frameSeconds);
        for (const sg::RenderPhase phase :
             {sg::RenderPhase::Load, sg::RenderPhase::Classify, sg::RenderPhase::Order,
              sg::RenderPhase::Upload, sg::RenderPhase::Draw, sg::RenderPhase::ReadBack}) {
            text += "," + csvNumber(phaseMs(r, phase));
        }
        text += "," + csvNumber(1e3 * r.ceilingSeconds) + "," + csvNumber(r.frameRatio) + "," +
                csvNumber(r.drawRatio) + "," + csvNumber(r.referenceRmse) + "," +
                csvNumber(r.referencePsnr) + "," + csvNumber(r.fullRmse) + "," +
                csvNumber(r.fullPsnr) + "," + csvNumber(r.fullFrameRatio) + "," + r.backend +
                "," + csvNumber(r.glFrameRatio) + "\n";
    }
    return text;
}

std::string benchPlotSvg(const std::vector<BenchResult>& results, const std::string& title) {
    const bool againstReference = std::any_of(results.begin(), results.end(), [](const auto& r) {
        return std::isfinite(r.referenceRmse) && r.referenceRmse > 0.0;
    });
    const auto error = [&](const BenchResult& r) {
        return againstReference ? r.referenceRmse : r.fullRmse;
    };
    struct Point {
        double ms;
        double error;
        const BenchResult* result;
    };
    std::vector<Point> points;
    std::vector<double> times;
    std::vector<double> errors;
    for (const BenchResult& r : results) {
        const double e = error(r);
        const double ms = 1e3 * r.frameSeconds;
        if (std::isfinite(e) && e > 0.0 && std::isfinite(ms) && ms > 0.0) {
            points.push_back({ms, e, &r});
            times.push_back(ms);
            errors.push_back(e);
        }
        if (r.isFullQuality && std::isfinite(r.ceilingSeconds) && r.ceilingSeconds > 0.0) {
            times.push_back(1e3 * r.ceilingSeconds);
        }
    }
    double xLo = 0.0;
    double xHi = 1.0;
    double yLo = 0.0;
    double yHi = 1.0;
    decadeRange(times, xLo, xHi);
    decadeRange(errors, yLo, yHi);
    const double plotWidth = kWidth - kLeft - kRight;
    const double plotHeight = kHeight - kTop - kBottom;
    const auto x = [&](double ms) {
        return kLeft + (std::log10(ms) - xLo) / (xHi - xLo) * plotWidth;
    };
    const auto y = [&](double e) {
        return kTop + plotHeight - (std::log10(e) - yLo) / (yHi - yLo) * plotHeight;
    };

    std::ostringstream svg;
    svg.precision(5);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\""
        << kHeight << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << kLeft << "\" y=\"22\" font-size=\"14\">" << escapeXml(title)
        << "</text>\n";
    // Grid and decade labels.
    for (int decade = static_cast<int>(xLo); decade <= static_cast<int>(xHi); ++decade) {
        for (int step = 1; step <= (decade < xHi ? 9 : 1); ++step) {
            const double value = step * std::pow(10.0, decade);
            svg << "<line x1=\"" << x(value) << "\" y1=\"" << kTop << "\" x2=\"" << x(value)
                << "\" y2=\"" << kTop + plotHeight << "\" stroke=\""
                << (step == 1 ? "#bbbbbb" : "#eeeeee") << "\"/>\n";
            if (step == 1 || step == 2 || step == 5) {
                svg << "<text x=\"" << x(value) << "\" y=\"" << kTop + plotHeight + 16
                    << "\" text-anchor=\"middle\">" << value << "</text>\n";
            }
        }
    }
    for (int decade = static_cast<int>(yLo); decade <= static_cast<int>(yHi); ++decade) {
        for (int step = 1; step <= (decade < yHi ? 9 : 1); ++step) {
            const double value = step * std::pow(10.0, decade);
            svg << "<line x1=\"" << kLeft << "\" y1=\"" << y(value) << "\" x2=\""
                << kLeft + plotWidth << "\" y2=\"" << y(value) << "\" stroke=\""
                << (step == 1 ? "#bbbbbb" : "#eeeeee") << "\"/>\n";
            if (step == 1) {
                svg << "<text x=\"" << kLeft - 6 << "\" y=\"" << y(value) + 4
                    << "\" text-anchor=\"end\">1e" << decade << "</text>\n";
            }
        }
    }
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << plotWidth
        << "\" height=\"" << plotHeight << "\" fill=\"none\" stroke=\"black\"/>\n";
    svg << "<text x=\"" << kLeft + plotWidth / 2 << "\" y=\"" << kHeight - 18
        << "\" text-anchor=\"middle\">median frame time (ms, log scale)</text>\n";
    svg << "<text transform=\"translate(18," << kTop + plotHeight / 2
        << ") rotate(-90)\" text-anchor=\"middle\">RMSE against "
        << (againstReference ? "the ray-cast reference" : "the full-quality texture splats")
        << " (log scale)</text>\n";

    // One colour per dataset and size; the legend on the right.
    std::map<std::string, std::size_t> series;
    for (const BenchResult& r : results) {
        series.emplace(r.dataset + " " + sizeText(r), series.size());
    }
    std::vector<std::string> seriesNames(series.size());
    for (const auto& [name, index] : series) {
        seriesNames[index] = name;
    }
    const auto colorOf = [&](const BenchResult& r) {
        return kColors[series.at(r.dataset + " " + sizeText(r)) % std::size(kColors)];
    };
    for (const BenchResult& r : results) {
        if (r.isFullQuality && std::isfinite(r.ceilingSeconds) && r.ceilingSeconds > 0.0) {
            const double cx = x(1e3 * r.ceilingSeconds);
            svg << "<line x1=\"" << cx << "\" y1=\"" << kTop << "\" x2=\"" << cx << "\" y2=\""
                << kTop + plotHeight << "\" stroke=\"" << colorOf(r)
                << "\" stroke-dasharray=\"5,4\"/>\n";
        }
    }
    for (const Point& p : points) {
        svg << marker(p.result->method, x(p.ms), y(p.error), colorOf(*p.result)) << "\n"
            << "<text x=\"" << x(p.ms) + 8 << "\" y=\"" << y(p.error) - 6
            << "\" font-size=\"10\" fill=\"" << colorOf(*p.result) << "\">"
            << escapeXml(p.result->method + (p.result->backend == "cpu" ? " (cpu)" : ""))
            << "</text>\n";
    }
    const double legendX = kLeft + plotWidth + 16;
    double legendY = kTop + 10;
    for (std::size_t i = 0; i < seriesNames.size(); ++i, legendY += 18) {
        svg << "<rect x=\"" << legendX << "\" y=\"" << legendY - 9 << "\" width=\"10\" "
            << "height=\"10\" fill=\"" << kColors[i % std::size(kColors)] << "\"/>"
            << "<text x=\"" << legendX + 16 << "\" y=\"" << legendY << "\">"
            << escapeXml(seriesNames[i]) << "</text>\n";
    }
    legendY += 8;
    const std::pair<const char*, const char*> methods[] = {
        {"texture", "texture, paper kernel"},
        {"texture-gaussian", "texture, Gaussian"},
        {"polygon", "polygon 3x7 Gaussian"},
        {"texture@", "octree cut (budget)"}};
    for (const auto& [method, label] : methods) {
        svg << marker(method, legendX + 5, legendY - 4, "#444444") << "<text x=\""
            << legendX + 16 << "\" y=\"" << legendY << "\">" << label << "</text>\n";
        legendY += 18;
    }
    svg << "<line x1=\"" << legendX << "\" y1=\"" << legendY - 4 << "\" x2=\"" << legendX + 10
        << "\" y2=\"" << legendY - 4 << "\" stroke=\"#444444\" stroke-dasharray=\"5,4\"/>"
        << "<text x=\"" << legendX + 16 << "\" y=\"" << legendY << "\">fill-rate ceiling</text>\n";
    svg << "</svg>\n";
    return svg.str();
}

void writeBenchCsv(const std::vector<BenchResult>& results, const std::string& path) {
    writeFileAtomically(path, benchCsv(results));
}

void writeBenchPlot(const std::vector<BenchResult>& results, const std::string& title,
                    const std::string& path) {
    requireFileExtension(path, {".svg"}, "plot");
    writeFileAtomically(path, benchPlotSvg(results, title));
}

} // namespace texsplat::bench
