#pragma once

// The scalar reference of render::cpu::compositeSplats() (SplatSpans.h) and the splats it is
// checked and timed on: the unit test (SplatSpansTest.cpp) holds the SIMD path to it, the
// micro-benchmark (tests/benchmarks/CpuRasterizerBenchmark.cpp) times the SIMD path against it.

#include "nodes/NodeTypes.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/VolumeData.h"
#include "nodes/bench/BenchDataset.h"
#include "nodes/bench/BenchMethod.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/ColorPlanes.h"
#include "nodes/render/cpu/SplatRaster.h"
#include "nodes/render/cpu/SplatSpans.h"
#include "octree/Splat.h"
#include "octree/VoxelSplats.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::test {

/// @brief FootprintSampler's lookup at square coordinates (a, b), before the length scale, one
/// pixel at a time: the radial cubic pieces at r = √(a² + b²) where the sampler has them (0
/// beyond the reach, where the SIMD loop skips the pixel), else the radial profile at a² + b² (linear between samples), or the padded
/// texture's bilinear lookup, with the clamps compositeSplats() applies.
inline float sampleFootprint(const render::cpu::FootprintSampler& sampler, float a, float b) {
    const float* values = sampler.values.data();
    if (sampler.hasPieces) {
        const float rho = a * a + b * b;
        if (!(rho <= sampler.reach)) {
            return 0.0f;
        }
        const float position =
            std::min(std::sqrt(rho) * sampler.piecesPerRadius,
                     render::cpu::FootprintSampler::kPieces - 1.0f);
        const float nearest = std::nearbyint(position); // halves to even, as the SIMD loop
        // Horner's rule without fused operations (std::fma is a library call without -mfma):
        // within an ulp of FootprintSampler::piece(), and a fair scalar baseline.
        const auto i = static_cast<std::size_t>(nearest);
        const float v = position - nearest;
        const auto& c = sampler.pieces;
        return ((c[3][i] * v + c[2][i]) * v + c[1][i]) * v + c[0][i];
    }
    if (sampler.isRadial) {
        constexpr float kSamples =
            static_cast<float>(render::cpu::FootprintSampler::kProfileSamples);
        const float position = std::min((a * a + b * b) * (0.5f * kSamples), kSamples);
        const float floor = std::floor(position);
        const auto index = static_cast<std::size_t>(floor);
        return (position - floor) * (values[index + 1] - values[index]) + values[index];
    }
    const float half = 0.5f * static_cast<float>(sampler.resolution);
    const float high = static_cast<float>(sampler.resolution) + 0.5f;
    const float s = std::clamp(a * half + half + 0.5f, 0.0f, high);
    const float t = std::clamp(b * half + half + 0.5f, 0.0f, high);
    const float s0 = std::floor(s);
    const float t0 = std::floor(t);
    const float fs = s - s0;
    const float ft = t - t0;
    const std::size_t stride = static_cast<std::size_t>(sampler.stride);
    const std::size_t index = static_cast<std::size_t>(t0) * stride + static_cast<std::size_t>(s0);
    const float bottom = fs * (values[index + 1] - values[index]) + values[index];
    const float top =
        fs * (values[index + stride + 1] - values[index + stride]) + values[index + stride];
    return ft * (top - bottom) + bottom;
}

/// @brief compositeSplats() as a plain scalar loop over the pixels of each splat's box: the same
/// map from a pixel to the square (1/w′ by division), the same depth and near/far tests, the same
/// footprint lookup (sampleFootprint()), and the emission-absorption of the definition rather
/// than its fast forms: α = 1 − e^(−τf) by std::expm1 at every optical depth, colour C·α/τ
/// (C·f for τ ≤ 1e-30), dst = min(src + (1 − α)·dst, FLT_MAX). A stamped splat's footprint is
/// its stamp (FootprintStamps::at()) at every pixel of its box. Returns the fragments
/// drawn: pixels inside a square (stamped: where the blend is not 0) and passing the depth tests,
/// summed over the splats.
inline std::uint64_t compositeSplatsScalar(const render::cpu::SplatRaster* splats,
                                           std::size_t count,
                                           const render::cpu::FootprintSampler& sampler,
                                           const render::cpu::FootprintStamps* stamps,
                                           render::cpu::ColorPlanes& planes, int rowBegin,
                                           int rowEnd) {
    using render::cpu::SplatRaster;
    std::uint64_t fragments = 0;
    const bool depthTest = planes.hasDepth();
    for (std::size_t i = 0; i < count; ++i) {
        const SplatRaster& splat = splats[i];
        const bool projective = (splat.flags & SplatRaster::kProjective) != 0;
        const bool clipped = (splat.flags & SplatRaster::kClipped) != 0;
        const bool stamped = (splat.flags & SplatRaster::kStamped) != 0;
        const float tau = splat.extinction;
        const float* q = splat.square;
        for (int row = std::max(splat.rowBegin, rowBegin); row < std::min(splat.rowEnd, rowEnd);
             ++row) {
            const auto y = static_cast<float>(row);
            for (int column = splat.columnBegin; column < splat.columnEnd; ++column) {
                const auto x = static_cast<float>(column);
                float a = q[0] * x + (q[1] * y + q[2]);
                float b = q[3] * x + (q[4] * y + q[5]);
                float f = 0.0f;
                if (stamped) {
                    f = stamps->at(splat.stampPhase, column - splat.stampColumn,
                                   row - splat.stampRow);
                } else {
                    if (projective) {
                        const float w = q[6] * x + (q[7] * y + q[8]);
                        if (!(w > 0.0f)) {
                            continue;
                        }
                        a /= w;
                        b /= w;
                    }
                    if (!(std::abs(a) <= 1.0f && std::abs(b) <= 1.0f)) {
                        continue;
                    }
                    f = std::max(sampleFootprint(sampler, a, b), 0.0f) * splat.lengthScale;
                }
                const float z = splat.depth[0] * x + (splat.depth[1] * y + splat.depth[2]);
                if (clipped && !(z >= -1.0f && z <= 1.0f)) {
                    continue;
                }
                if (depthTest && !(0.5f * z + 0.5f < planes.depth(row)[column])) {
                    continue;
                }
                fragments += stamped && f == 0.0f ? 0 : 1;
                const float alpha = -std::expm1(-tau * f);
                const float weight = tau > 1e-30f ? alpha / tau : f;
                const float transmitted = 1.0f - alpha;
                float* destinations[4] = {planes.red(row), planes.green(row), planes.blue(row),
                                          planes.alpha(row)};
                const float sources[4] = {std::min(splat.color[0] * weight, FLT_MAX),
                                          std::min(splat.color[1] * weight, FLT_MAX),
                                          std::min(splat.color[2] * weight, FLT_MAX), alpha};
                for (int channel = 0; channel < 4; ++channel) {
                    float& destination = destinations[channel][column];
                    destination = std::min(sources[channel] + transmitted * destination, FLT_MAX);
                }
            }
        }
    }
    return fragments;
}

/// @brief Where the camera of a CompositeWorkload looks from.
enum class WorkloadCamera {
    Orthographic, ///< `texsplat bench`'s direction, orthographic: one affine map for all splats
    Perspective,  ///< `texsplat bench`'s perspective camera: a homography per splat
    Inside, ///< that camera moved to the volume's centre, its near plane a tenth of the volume's
            ///< size away: splats behind the eye and across the near plane, clipped per pixel
    OrthographicClose, ///< the orthographic camera showing a third of the height: splats three
                       ///< times as wide, many across the image's borders
};

/// @brief The splats of one `texsplat bench` frame set up for compositeSplats(), in order.
struct CompositeWorkload {
    std::vector<render::cpu::SplatRaster> splats; ///< back to front, those covering a pixel
    std::vector<render::cpu::RowSpan> rows;       ///< the rows of each of `splats`
    std::vector<std::size_t> sources;             ///< each one's index in the frame's list
    std::shared_ptr<const render::cpu::FootprintSampler> sampler; ///< the batch's footprint
    std::shared_ptr<const render::cpu::SplatSetup> setup;         ///< what set them up
    /// @brief The batch's voxels when it is a full-resolution grid's (FrameSplats::voxels: what
    /// compositeVoxels() walks), else null.
    std::shared_ptr<const octree::VoxelSplats> voxels;
    int width = 0;                                                ///< image columns
    int height = 0;                                               ///< image rows

    /// @brief The stamps of the stamped splats, or null.
    const render::cpu::FootprintStamps* stamps() const { return setup->stamps(); }
};

/// @brief `splats` set up by `setup`, in order.
inline std::vector<render::cpu::SplatRaster> setUpSplats(const render::cpu::SplatSetup& setup,
                                                         const std::vector<octree::Splat>& splats) {
    std::vector<render::cpu::SplatRaster> rasters(splats.size());
    setup.setUp(splats.data(), splats.size(), rasters.data());
    return rasters;
}

/// @brief The splats `texsplat bench` draws for `dataset` ("blob64") with `method` ("texture",
/// "polygon"; full resolution) in a `size` x `size` image, through `camera`, collected by
/// FrameAction and set up by SplatSetup as CpuRenderer sets them up (a radial footprint's pixel
/// boxes bounding its disc, without `discRadius` the square's boxes; stamped where the
/// footprint suits it, unless not `stamped`).
inline CompositeWorkload compositeWorkload(const std::string& dataset, const std::string& method,
                                           WorkloadCamera camera, int size,
                                           bool discRadius = true, bool stamped = true) {
    nodes::registerNodeTypes();
    const bench::BenchDataset source = bench::BenchDataset::fromName(dataset);
    const bool orthographic =
        camera == WorkloadCamera::Orthographic || camera == WorkloadCamera::OrthographicClose;
    const sg::Separator::Ptr root =
        source.scene(bench::BenchMethod::fromName(method).makeNode(0), 1.0f,
                     orthographic ? render::FramingCamera::Orthographic
                                  : render::FramingCamera::Perspective);
    const auto& volume = static_cast<const nodes::VolumeData&>(*root->child(2));
    if (camera == WorkloadCamera::OrthographicClose) {
        auto& close = static_cast<nodes::OrthographicCamera&>(*root->child(0));
        close.height.setValue(close.height.value() / 3.0f);
    }
    if (camera == WorkloadCamera::Inside) {
        auto& perspective = static_cast<nodes::Camera&>(*root->child(0));
        perspective.position.setValue(volume.bounds().center());
        perspective.nearDistance.setValue(0.1f * glm::length(volume.bounds().size()));
    }
    render::FrameAction action(size, size);
    const render::FrameSplats& batch = action.collect(*root).splats.front();
    CompositeWorkload workload;
    workload.sampler = std::make_shared<const render::cpu::FootprintSampler>(*batch.footprint);
    workload.width = size;
    workload.height = size;
    // As CpuRenderer sets them up: a radial footprint's boxes bound its disc.
    auto setup = std::make_shared<render::cpu::SplatSetup>(
        batch.view, static_cast<float>(batch.footprint->extent), size, size,
        discRadius && workload.sampler->isRadial ? std::sqrt(workload.sampler->reach) : 0.0f);
    if (stamped) {
        setup->setStamps(setup->stampsFor(*workload.sampler));
    }
    workload.setup = setup;
    workload.voxels = batch.voxels;
    const std::vector<render::cpu::SplatRaster> rasters =
        setUpSplats(*setup, batch.list()->splats());
    for (std::size_t i = 0; i < rasters.size(); ++i) {
        if (!rasters[i].isEmpty()) {
            workload.splats.push_back(rasters[i]);
            workload.rows.push_back(render::cpu::rowSpanOf(rasters[i]));
            workload.sources.push_back(i);
        }
    }
    return workload;
}

} // namespace texsplat::test
