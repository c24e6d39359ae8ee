#pragma once

#include "GlTestSupport.h"
#include "nodes/Camera.h"
#include "nodes/NodeTypes.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/image/Image.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/Grid.h"
#include "nodes/volume/RawVolume.h"
#include "nodes/render/Frame.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/gl/GlRenderer.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "scenegraph/Node.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace texsplat::test {

/// @brief Draws `frame` (made by hand, so that splat drawing is tested through the GL backend's
/// real passes without the scene nodes) with a new GL backend; reads color and depth back.
inline image::Image drawFrame(const render::Frame& frame) {
    render::GlRenderer renderer;
    sg::RenderStatistics statistics;
    return renderer.draw(frame, statistics, true);
}

/// @brief An orthographic camera looking down −z at the square [x0, x0 + size]² in the plane
/// z = 0, from z = 10.
inline render::SplatView topView(float x0, float size, const glm::vec3& spacing = glm::vec3(1.0f)) {
    const glm::mat4 view =
        glm::lookAt(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 projection = glm::ortho(x0, x0 + size, x0, x0 + size, 1.0f, 20.0f);
    return render::SplatView::fromMatrices(glm::mat4(1.0f), view, projection, spacing);
}

/// @brief Writes `grid` (a ScalarGrid or VectorGrid) as a raw file in the test's temporary folder
/// and answers its path.
template <class Grid> std::string writeTestVolume(const std::string& name, const Grid& grid) {
    const std::string path = ::testing::TempDir() + "texsplat_render_" + name + ".raw";
    volume::writeRawVolume(path, grid);
    return path;
}

/// @brief A VolumeData node that reads `path` (raw or OpenVDB, as `source` says; `gridName` picks
/// an OpenVDB grid).
inline nodes::VolumeData::Ptr fileVolume(nodes::VolumeSource source, const std::string& path,
                                         const std::string& gridName = std::string()) {
    nodes::VolumeData::Ptr volume = nodes::VolumeData::create();
    volume->source.setValue(source);
    volume->fileName.setValue(path);
    volume->gridName.setValue(gridName);
    return volume;
}

/// @brief One rendered frame: the image (color and depth) and what the action and the backend
/// counted.
struct RenderedFrame {
    image::Image image;
    sg::RenderStatistics statistics;
};


/// @brief Points `camera` so that the whole of `root` (its bounding box) fills the view.
inline void frameCamera(nodes::Camera& camera, sg::Node& root) {
    sg::BoundingBoxAction box;
    box.apply(root);
    camera.viewAll(box.boundingBox(), 1.0f);
}

/// @brief A Separator of `camera` followed by `nodes`, with the camera framed on the scene.
inline sg::Separator::Ptr framedScene(const nodes::Camera::Ptr& camera,
                                      const std::vector<sg::Node::Ptr>& nodes) {
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(camera);
    for (const sg::Node::Ptr& node : nodes) {
        root->addChild(node);
    }
    frameCamera(*camera, *root);
    return root;
}
/// @brief Collects the frame of `root` with a new action and draws it with a new GL backend;
/// answers the image and the frame's statistics.
inline RenderedFrame renderFrame(sg::Node& root, int width, int height) {
    nodes::registerNodeTypes();
    render::FrameAction action(width, height);
    render::GlRenderer renderer;
    image::Image image = renderer.draw(action.collect(root), action.statistics(), true);
    return {std::move(image), action.statistics()};
}

/// @brief Renders `root` with a new action and backend and reads color and depth back.
inline image::Image renderScene(sg::Node& root, int width, int height) {
    return renderFrame(root, width, height).image;
}

/// @brief Whether every pixel is finite and at least one has color.
inline void expectFiniteAndNotEmpty(const image::Image& image, const std::string& what) {
    const image::Image::Statistics statistics = image.statistics();
    EXPECT_EQ(statistics.nonFinitePixels, 0u) << what;
    EXPECT_GT(statistics.maximum.r + statistics.maximum.g + statistics.maximum.b, 0.0) << what;
}

/// @brief Whether every pixel is finite, with no negative color and alpha in [0, 1] (up to a
/// rounding of the blend), as "over" compositing of physical splats must leave it.
inline void expectFiniteWithAlphaInRange(const image::Image& image, const std::string& what) {
    const image::Image::Statistics statistics = image.statistics();
    EXPECT_EQ(statistics.nonFinitePixels, 0u) << what;
    EXPECT_GE(statistics.minimum.a, 0.0) << what;
    EXPECT_LE(statistics.maximum.a, 1.0 + 1e-6) << what;
    EXPECT_GE(std::min({statistics.minimum.r, statistics.minimum.g, statistics.minimum.b}), 0.0)
        << what;
}

// The paper's figure 2 (Crawfis & Max 1993, section 2): one layer of glowing, completely
// transparent splats projected along z; the sum of footprints has max 1.00249 at (.5, .5) and
// min 0.99845 at (.25, .25) relative to its mean 1.
constexpr double kPaperLayerMax = 1.00249;
constexpr double kPaperLayerMin = 0.99845;

// Figure 2 set-up: a 16 x 16 layer of unit voxels, 8 pixels per voxel, pixel centres on the
// lattice points k/8 (so they hit (.5,.5) and (.25,.25)), the interior keeps 2 voxels (more than
// the support 1.556) from the layer's edge.
constexpr int kLayerVoxels = 16;
constexpr int kPixelsPerVoxel = 8;
constexpr int kLayerImageSize = kLayerVoxels * kPixelsPerVoxel;
constexpr int kLayerInteriorLow = 2 * kPixelsPerVoxel;
constexpr int kLayerInteriorHigh = (kLayerVoxels - 3) * kPixelsPerVoxel;

/// @brief Mean and extremes of a figure-2 layer image over its interior.
struct LayerStatistics {
    double mean = 0.0;
    double max = 0.0;
    double min = 0.0;
    double relativeMax() const { return max / mean; }
    double relativeMin() const { return min / mean; }
};

/// @brief LayerStatistics of one channel (`red`, `width` values a row) over the interior
/// [kLayerInteriorLow, kLayerInteriorHigh]² pixels.
inline LayerStatistics layerInteriorStatistics(const std::vector<float>& red, int width) {
    LayerStatistics statistics;
    statistics.max = -std::numeric_limits<double>::infinity();
    statistics.min = std::numeric_limits<double>::infinity();
    double sum = 0.0;
    int count = 0;
    for (int y = kLayerInteriorLow; y <= kLayerInteriorHigh; ++y) {
        for (int x = kLayerInteriorLow; x <= kLayerInteriorHigh; ++x) {
            const double value = red[static_cast<std::size_t>(y * width + x)];
            sum += value;
            ++count;
            statistics.max = std::max(statistics.max, value);
            statistics.min = std::min(statistics.min, value);
        }
    }
    statistics.mean = sum / count;
    return statistics;
}

/// @brief Prints a layer's numbers in the test output ("figure2 <what>: mean … max/mean …").
inline void reportLayer(const char* what, const LayerStatistics& statistics) {
    std::printf("figure2 %s: mean %.6f max/mean %.6f min/mean %.6f\n", what, statistics.mean,
                statistics.relativeMax(), statistics.relativeMin());
}

/// @brief The layer statistics of the red channel of `image` (a kLayerImageSize² image).
inline LayerStatistics redLayerStatistics(const image::Image& image) {
    std::vector<float> red;
    for (const glm::vec4& color : image.pixels()) {
        red.push_back(color.r);
    }
    return layerInteriorStatistics(red, kLayerImageSize);
}

/// @brief The paper's figure 2 as a scene: a raw file (named after `name`) of one
/// kLayerVoxels² layer of value 1, classified to emission 1 and no opacity, drawn by TextureSplat
/// (paper kernel, default texture) through an orthographic camera looking down z whose pixel
/// centres lie on the lattice k/kPixelsPerVoxel (the view's left edge half a pixel left of voxel
/// 0's centre), for a kLayerImageSize² image.
inline sg::Separator::Ptr figure2LayerScene(const std::string& name) {
    volume::DenseGrid<float> layer{
        volume::GridGeometry(glm::i64vec3(kLayerVoxels, kLayerVoxels, 1))};
    for (int j = 0; j < kLayerVoxels; ++j) {
        for (int i = 0; i < kLayerVoxels; ++i) {
            layer.setValue({i, j, 0}, 1.0f);
        }
    }
    nodes::TransferFunction::Ptr glow = nodes::TransferFunction::create();
    glow->colorValues.setValue({0.0f, 1.0f});
    glow->colors.setValue({glm::vec3(1.0f), glm::vec3(1.0f)});
    glow->opacities.setValue({0.0f, 0.0f});
    glow->emission.setValue(1.0f);
    const float pixel = 1.0f / kPixelsPerVoxel;
    const float half = 0.5f * static_cast<float>(kLayerVoxels);
    nodes::OrthographicCamera::Ptr camera = nodes::OrthographicCamera::create();
    camera->position.setValue(glm::vec3(half - 0.5f * pixel, half - 0.5f * pixel, 10.0f));
    camera->height.setValue(static_cast<float>(kLayerVoxels));
    camera->nearDistance.setValue(1.0f);
    camera->farDistance.setValue(20.0f);
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(camera);
    root->addChild(glow);
    root->addChild(
        fileVolume(nodes::VolumeSource::FileRaw, writeTestVolume(name, layer)));
    root->addChild(nodes::TextureSplat::create());
    return root;
}

} // namespace texsplat::test
