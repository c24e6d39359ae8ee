#include "nodes/kernel/KernelPlot.h"

#include "SceneNodesTestSupport.h"
#include "nodes/kernel/CubicKernel.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using texsplat::kernel::CubicKernel;
using texsplat::nodes::test::errorOf;

TEST(KernelPlot, svgHasBothCurvesAndTheKernelsDescription) {
    const CubicKernel kernel = CubicKernel::paper();
    const std::string svg = texsplat::kernel::kernelPlotSvg(kernel);
    EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    size_t polylines = 0;
    for (size_t at = svg.find("<polyline"); at != std::string::npos;
         at = svg.find("<polyline", at + 1))
        ++polylines;
    EXPECT_EQ(polylines, 2u);
    EXPECT_NE(svg.find(kernel.description()), std::string::npos);
}

TEST(KernelPlot, writesTheFileOrThrowsIoError) {
    const CubicKernel kernel = CubicKernel::paper();
    const std::string path = ::testing::TempDir() + "kernel_plot_test.svg";
    texsplat::kernel::writeKernelPlot(kernel, path);
    std::ifstream file(path);
    std::stringstream contents;
    contents << file.rdbuf();
    EXPECT_EQ(contents.str(), texsplat::kernel::kernelPlotSvg(kernel));
    std::remove(path.c_str());
    EXPECT_THROW(texsplat::kernel::writeKernelPlot(kernel, "/nonexistent-directory/plot.svg"),
                 texsplat::IoError);
}

TEST(KernelPlot, onlySvgFileNamesAreWritten) {
    const CubicKernel kernel = CubicKernel::paper();
    const std::string path = ::testing::TempDir() + "kernel_plot_test.png";
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { texsplat::kernel::writeKernelPlot(kernel, path); }),
              path + ": unknown plot extension '.png' (supported: .svg)");
    EXPECT_FALSE(std::ifstream(path).good());
    const std::string upper = ::testing::TempDir() + "kernel_plot_test.SVG";
    texsplat::kernel::writeKernelPlot(kernel, upper);
    EXPECT_TRUE(std::ifstream(upper).good());
    std::remove(upper.c_str());
}
