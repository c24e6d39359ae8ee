#pragma once

#include "nodes/kernel/RadialKernel.h"

#include <string>

namespace texsplat::kernel {

/// @brief The SVG text of a plot of the kernel profile g(r) and its footprint f(r) over
/// r ∈ [0, 1.05 t] (the paper's figure 1 plus the footprint), with axes, ticks and a legend.
std::string kernelPlotSvg(const RadialKernel& kernel);

/// @brief Writes kernelPlotSvg(kernel) to path all at once (scenegraph/AtomicFile.h). Throws
/// IoError, and writes nothing, unless path ends in `.svg` (any case; "p.png: unknown plot
/// extension '.png' (supported: .svg)"), or when the file cannot be written.
void writeKernelPlot(const RadialKernel& kernel, const std::string& path);

} // namespace texsplat::kernel
