#include "nodes/bench/LegibilityBench.h"

#include "nodes/NodeTypes.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/TransferFunction.h"
#include "nodes/VectorSplat.h"
#include "nodes/VolumeData.h"
#include "nodes/image/ImageIo.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/volume/DenseGrid.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/Seconds.h"
#ifdef TEXSPLAT_WITH_GL
#include "nodes/render/gl/GlRenderer.h"
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace texsplat::bench {
namespace {

// Voxels of margin around the grid in the image, and voxels of it left out of the measure at
// each side (the marks thin out where the data ends) and about a singular centre.
constexpr float kMargin = 2.0f;
constexpr float kBorder = 2.0f;

// The field at a point (voxel units from the grid's centre, y up).
glm::vec2 fieldAt(const LegibilityCase& what, float x, float y) {
    switch (what.field) {
    case LegibilityField::Vortex:
        return {-y, x};
    case LegibilityField::Saddle:
        return {x, -y};
    case LegibilityField::Uniform:
        break;
    }
    const float angle = what.angle * 3.14159265f / 180.0f;
    return {std::cos(angle), std::sin(angle)};
}

int imageSize(const LegibilityCase& what) {
    return static_cast<int>(std::lround((what.voxels + 2.0f * kMargin) * what.pixelsPerVoxel));
}

// Pixel centre (x, y) of the image → voxel units from the grid's centre, y up.
glm::vec2 fromCentre(const LegibilityCase& what, float x, float y) {
    const float half = 0.5f * static_cast<float>(imageSize(what));
    return glm::vec2(x - half, half - y) / what.pixelsPerVoxel;
}

const char* fieldName(LegibilityField field) {
    switch (field) {
    case LegibilityField::Vortex:
        return "vortex";
    case LegibilityField::Saddle:
        return "saddle";
    case LegibilityField::Uniform:
        break;
    }
    return "uniform";
}

// One frame of `root` (collected and drawn) by `backend`, and how long it took.
image::Image drawFrame(sg::Node& root, int size, render::Backend backend, double& seconds) {
    const sg::TimingClock::time_point start = sg::TimingClock::now();
    render::FrameAction action(size, size);
    const render::Frame& frame = action.collect(root);
    image::Image image = [&] {
#ifdef TEXSPLAT_WITH_GL
        if (backend == render::Backend::Gl) {
            render::GlRenderer renderer;
            return renderer.draw(frame, action.statistics(), false);
        }
#endif
        static_cast<void>(backend);
        return render::cpu::CpuRenderer().draw(frame, action.statistics(), false);
    }();
    seconds = sg::secondsSince(start);
    return image;
}

} // namespace

sg::Node::Ptr legibilityScene(const LegibilityCase& what) {
    nodes::registerNodeTypes(); // the methods the frame's action calls
    const int n = what.voxels;
    auto grid = std::make_shared<volume::DenseVectorGrid>(volume::GridGeometry({n, n, n}));
    const float centre = 0.5f * static_cast<float>(n - 1);
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                const glm::vec2 flow =
                    fieldAt(what, static_cast<float>(i) - centre, static_cast<float>(j) - centre);
                grid->setValue({i, j, k}, glm::vec3(flow, 0.0f));
            }
        }
    }
    auto data = nodes::VolumeData::create();
    data->setGrid(grid);
    auto camera = nodes::OrthographicCamera::create();
    camera->position.setValue(glm::vec3(centre, centre, centre + 3.0f * static_cast<float>(n)));
    camera->nearDistance.setValue(static_cast<float>(n));
    camera->farDistance.setValue(5.0f * static_cast<float>(n));
    camera->focalDistance.setValue(3.0f * static_cast<float>(n));
    camera->height.setValue(static_cast<float>(n) + 2.0f * kMargin);
    auto marks = nodes::VectorSplat::create();
    marks->colorMode.setValue(nodes::VectorColorMode::Constant);
    marks->color.setValue(glm::vec3(1.0f));
    marks->markType.setValue(what.type);
    auto scene = sg::Separator::create();
    scene->addChild(camera);
    scene->addChild(nodes::TransferFunction::create());
    scene->addChild(data);
    scene->addChild(marks);
    return scene;
}

ImageFlow legibilityFlow(const LegibilityCase& what) {
    return [what](float x, float y) {
        const glm::vec2 at = fromCentre(what, x, y);
        const glm::vec2 flow = fieldAt(what, at.x, at.y);
        return glm::vec2(flow.x, -flow.y); // y down in the image
    };
}

LegibilityResult measureLegibility(const LegibilityCase& what, const LegibilityOptions& options) {
    LegibilityResult result;
    result.what = what;
    const int size = imageSize(what);
    result.width = size;
    const sg::Node::Ptr scene = legibilityScene(what);
    double seconds = 0.0;
    image::Image image = drawFrame(*scene, size, what.backend, seconds); // untimed: loading
    std::vector<double> times;
    for (int i = 0; i < options.repeat; ++i) {
        image = drawFrame(*scene, size, what.backend, seconds);
        times.push_back(seconds);
    }
    if (!times.empty()) {
        std::nth_element(times.begin(),
                         times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2),
                         times.end());
        result.frameSeconds = times[times.size() / 2];
    } else {
        result.frameSeconds = seconds;
    }
    if (!options.imagePath.empty()) {
        image::writeImage(image, options.imagePath);
    }
    const float inside = 0.5f * static_cast<float>(what.voxels - 1) - kBorder;
    const bool singular = what.field != LegibilityField::Uniform;
    const auto isMeasured = [&](int x, int y) {
        const glm::vec2 at =
            fromCentre(what, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        return std::abs(at.x) < inside && std::abs(at.y) < inside &&
               !(singular && glm::length(at) < kBorder);
    };
    const ImageFlow flow = legibilityFlow(what);
    const double smoothing = 0.5 * what.pixelsPerVoxel;
    const GrayImage gray = displayedLuminance(image);
    result.marks = streakAngles(gray, flow, smoothing, isMeasured);
    if (options.reference) {
        const int halfLength = static_cast<int>(std::lround(2.5f * what.pixelsPerVoxel)) + 4;
        result.reference = streakAngles(lineIntegralConvolution(size, size, flow, halfLength), flow,
                                        smoothing, isMeasured);
    }
    result.skew = downstreamSkew(gray, flow, isMeasured);
    if (what.field == LegibilityField::Uniform) {
        result.orientation = streakOrientation(gray, isMeasured);
    }
    return result;
}

std::vector<LegibilityCase> legibilityCases(const std::vector<render::Backend>& backends) {
    std::vector<LegibilityCase> cases;
    for (const render::Backend backend : backends) {
        for (const render::MarkType type :
             {render::MarkType::Scratches, render::MarkType::Particles}) {
            LegibilityCase what;
            what.backend = backend;
            what.type = type;
            for (const LegibilityField field : {LegibilityField::Vortex, LegibilityField::Saddle}) {
                what.field = field;
                for (const float zoom : {4.0f, 6.0f, 10.0f, 16.0f}) {
                    what.pixelsPerVoxel = zoom;
                    cases.push_back(what);
                }
            }
            what.field = LegibilityField::Uniform;
            for (const float angle : {0.0f, 30.0f, 60.0f, 90.0f, 135.0f}) {
                what.angle = angle;
                for (const float zoom : {4.0f, 16.0f}) {
                    what.pixelsPerVoxel = zoom;
                    cases.push_back(what);
                }
            }
        }
    }
    return cases;
}

std::string legibilityImageName(const LegibilityCase& what) {
    std::string name = fieldName(what.field);
    if (what.field == LegibilityField::Uniform) {
        name += std::to_string(static_cast<int>(std::lround(what.angle)));
    }
    name += what.type == render::MarkType::Scratches ? "-scratches" : "-particles";
    name += what.backend == render::Backend::Gl ? "-gl-" : "-cpu-";
    return name + std::to_string(static_cast<int>(std::lround(what.pixelsPerVoxel))) + ".png";
}

std::string legibilityTableHeader() {
    return "  field        marks      backend  px/voxel  image      median    p90  LIC median  "
           "LIC p90   skew  orientation  frame\n";
}

std::string legibilityTableRow(const LegibilityResult& row) {
    std::string field = fieldName(row.what.field);
    char orientation[32] = "";
    if (row.what.field == LegibilityField::Uniform) {
        char angle[32];
        std::snprintf(angle, sizeof(angle), " %g°", static_cast<double>(row.what.angle));
        field += angle;
        std::snprintf(orientation, sizeof(orientation), "%.1f°", row.orientation);
    }
    char line[256];
    std::snprintf(line, sizeof(line),
                  "  %-12s %-10s %-8s %8g  %4dx%-4d %5.1f° %5.1f°      %5.1f°   %5.1f°  "
                  "%5.2f  %11s  %.3f s\n",
                  field.c_str(),
                  row.what.type == render::MarkType::Scratches ? "SCRATCHES" : "PARTICLES",
                  row.what.backend == render::Backend::Gl ? "gl" : "cpu",
                  static_cast<double>(row.what.pixelsPerVoxel), row.width, row.width,
                  row.marks.median, row.marks.percentile90, row.reference.median,
                  row.reference.percentile90, row.skew, orientation, row.frameSeconds);
    return line;
}

std::string legibilityTable(const std::vector<LegibilityResult>& rows) {
    std::string table = legibilityTableHeader();
    for (const LegibilityResult& row : rows) {
        table += legibilityTableRow(row);
    }
    return table;
}

} // namespace texsplat::bench
