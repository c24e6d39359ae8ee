/// @file
/// @brief A program's own array rendered with texsplat, in ten lines: the array becomes a grid
/// without a copy (volume::ExternalGrid), a VolumeData node draws it through a transfer function
/// (its range taken from the data) as the paper's texture splats, render::sceneImage() frames
/// and renders the scene on the CPU (no GL, no display) and image::writeImage() writes the PNG.
///
/// Then the same data as a figure (`out-figure.png`): seen at an angle, on white, with a titled
/// colour bar beside it (render::framedScene(), annotation::ColorLegend).
///
/// Usage: `texsplat_example_render_array [out.png]` (default array.png). Built and run by CMake
/// (examples/CMakeLists.txt) and by the installed-package test (tests/install), so it builds
/// against an installed texsplat as a user's program does; docs/embedding.md walks through it.

#include "nodes/NodeTypes.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/annotation/ColorLegend.h"
#include "nodes/image/ImageIo.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/SceneImage.h"
#include "nodes/volume/ExternalGrid.h"
#include "scenegraph/Separator.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace texsplat;

// The program's data: 64³ floats, x fastest, here two overlapping Gaussian blobs.
std::vector<float> simulation(int n) {
    std::vector<float> values(static_cast<std::size_t>(n) * n * n);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const auto blob = [&](float cx, float cy, float cz, float width) {
                    const float dx = x - cx, dy = y - cy, dz = z - cz;
                    return std::exp(-(dx * dx + dy * dy + dz * dz) / (width * width));
                };
                values[x + n * (y + static_cast<std::size_t>(n) * z)] =
                    blob(0.4f * n, 0.5f * n, 0.5f * n, 0.2f * n) +
                    0.6f * blob(0.65f * n, 0.45f * n, 0.55f * n, 0.12f * n);
            }
    return values;
}

int main(int argc, char** argv) {
    const std::string output = argc > 1 ? argv[1] : "array.png";
    const int n = 64;
    const std::vector<float> values = simulation(n);

    nodes::registerNodeTypes();
    auto data = nodes::VolumeData::create();
    data->setGrid(std::make_shared<volume::ExternalScalarGrid>(volume::GridGeometry({n, n, n}),
                                                               values.data(), values.size()));
    auto scene = sg::Separator::create();
    scene->addChild(data);
    scene->addChild(nodes::TransferFunction::create());
    scene->addChild(nodes::TextureSplat::create());
    image::writeImage(render::sceneImage(scene, {512, 512}), output);
    std::printf("render-array: wrote %s (512 x 512, %d^3 voxels)\n", output.c_str(), n);

    // The same data as a figure: a camera angle, a white background and a titled colour bar.
    auto transfer = std::static_pointer_cast<nodes::TransferFunction>(scene->child(1));
    transfer->preset.setValue(nodes::ColorPreset::Viridis);
    transfer->title.setValue("Concentration");
    transfer->units.setValue("mol/m³");
    render::Framing view;
    view.direction = glm::vec3(1.0f, -0.6f, -1.0f); // looking along this
    view.up = glm::vec3(0.0f, 1.0f, 0.0f);          // y up in the image
    const sg::Node::Ptr framed = render::framedScene(scene, 1.0f, view);
    const glm::vec4 white(1.0f);
    const image::Image picture = render::sceneImage(framed, {512, 512, white});
    const annotation::ColorLegend legend(annotation::ColorBar::ofScene(*framed), {}, 512, 512);
    const std::string figure = output.substr(0, output.rfind('.')) + "-figure.png";
    image::writeImage(legend.compose(picture, white), figure);
    std::printf("render-array: wrote %s (%d x %d, with its colour bar)\n", figure.c_str(),
                legend.figureSize().x, legend.figureSize().y);
    return 0;
}
