#pragma once

#include "nodes/bench/BenchResult.h"

#include <string>
#include <vector>

namespace texsplat::bench {

/// @brief The results as a fixed-width table for a terminal, one row per result: splats,
/// fragments (the method's and the fill-rate ceiling's), median frame, draw and ceiling times
/// in milliseconds, the ratios frame/ceiling and draw/ceiling, and RMSE/PSNR against the
/// reference and against the full-quality image ("-" where not measured).
std::string benchTable(const std::vector<BenchResult>& results);

/// @brief The results as CSV with a header row: `dataset,width,height,method,full_quality,
/// splats,fragments,ceiling_fragments,frame_ms,load_ms,classify_ms,order_ms,upload_ms,draw_ms,
/// read_back_ms,ceiling_ms,frame_ratio,draw_ratio,reference_rmse,reference_psnr,full_rmse,
/// full_psnr,full_frame_ratio,backend,gl_frame_ratio`; a value not measured is empty, an
/// infinite PSNR is `inf`.
std::string benchCsv(const std::vector<BenchResult>& results);

/// @brief An SVG plot of error against frame time, both on log scales: one colour per dataset
/// and size, one marker per method, and that series' fill-rate ceiling (full list) as a dashed
/// vertical line. The error is the RMSE against the reference where there is one, else against
/// the full-quality image (which is then left out: its error is 0). `title` heads the plot.
std::string benchPlotSvg(const std::vector<BenchResult>& results, const std::string& title);

/// @brief Writes benchCsv(results) to `path` atomically. @throws IoError.
void writeBenchCsv(const std::vector<BenchResult>& results, const std::string& path);

/// @brief Writes benchPlotSvg(results, title) to `path` atomically. @throws IoError.
void writeBenchPlot(const std::vector<BenchResult>& results, const std::string& title,
                    const std::string& path);

} // namespace texsplat::bench
