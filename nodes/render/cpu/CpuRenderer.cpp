#include "nodes/render/cpu/CpuRenderer.h"

#include "nodes/kernel/FootprintTexture.h"
#include "nodes/render/ScreenMarks.h"
#include "nodes/render/cpu/ColorPlanes.h"
#include "nodes/render/cpu/MarkRaster.h"
#include "nodes/render/cpu/MeshRasterizer.h"
#include "nodes/render/cpu/SplatRaster.h"
#include "nodes/render/cpu/SplatSpans.h"
#include "nodes/render/cpu/VoxelRaster.h"
#include "nodes/render/cpu/VoxelSpans.h"
#include "nodes/render/cpu/detail/SamplerCache.h"
#include "nodes/render/detail/DepthOrderedRuns.h"
#include "octree/Splat.h"
#include "octree/SplatEmission.h"
#include "octree/VoxelSplats.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Seconds.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace texsplat::render::cpu {
namespace {

using Clock = sg::TimingClock;
using sg::secondsSince;

// Splats set up at a time: their rasters (about 90 bytes each) stay in the caches while the
// bands composite them, and memory does not grow with the splat count.
constexpr std::size_t kChunk = 16384;

// Rows of the image split into bands, a few per thread so that the threads stay busy where
// the volume covers only part of the image.
struct Bands {
    int rows;
    int count;
    Bands(int height, int threads)
        : rows(std::max(4, (height + 4 * threads - 1) / (4 * threads))),
          count((height + rows - 1) / rows) {}
    int begin(int band) const { return band * rows; }
    int end(int band, int height) const { return std::min(height, (band + 1) * rows); }
};

// Rows of the image split into bands for voxel batches (compositeVoxels()): each band
// composites every slice while its rows stay in the caches, so bands are no taller than
// kVoxelBandRows (128 rows of four float planes at 512 columns: 1.2 MiB, within a core's L2
// here; measured 0.96x the frame of 64-row bands). The bands cover only the rows the grid
// reaches (VoxelRaster::rowRange()), in equal heights, and their count is a multiple of the
// threads: each thread draws as many rows of the volume as the others and they finish
// together, and a band is as tall with two threads as with one (a splat across two bands is
// placed in both: thinner bands place more).
struct VoxelBands {
    static constexpr int kVoxelBandRows = 128;
    int first; // the first row of the first band
    int last;  // the end of the last band
    int rows;
    int count;
    VoxelBands(std::pair<int, int> range, int threads) : first(range.first), last(range.second) {
        const int covered = last - first;
        const int fewest = (covered + kVoxelBandRows - 1) / kVoxelBandRows;
        const int bands = std::max(1, (fewest + threads - 1) / threads * threads);
        rows = std::max(4, (covered + bands - 1) / bands);
        count = covered > 0 ? (covered + rows - 1) / rows : 0;
    }
    int begin(int band) const { return first + band * rows; }
    int end(int band) const { return std::min(last, first + (band + 1) * rows); }
};

// One splat batch of the frame ready for the rasterizer.
struct PreparedBatch {
    const FrameSplats* splats;
    std::unique_ptr<const SplatSetup> setup;         // the scalar splats (none: marks only)
    std::shared_ptr<const FootprintSampler> sampler; // their footprint
    std::vector<ScreenMark> marks;                   // vector and combined splats
    MarkStyle style;                                 // how the marks are coloured
};

std::vector<PreparedBatch> prepareBatches(const Frame& frame, detail::SamplerCache& cache) {
    std::vector<PreparedBatch> batches;
    for (const FrameSplats& splats : frame.splats) {
        const SplatFootprint& footprint = *splats.footprint;
        PreparedBatch batch;
        batch.splats = &splats;
        if (footprint.hasMarks()) {
            makeScreenMarks(splats, frame.width, frame.height, batch.marks);
            batch.style.type = splats.marks.type;
            batch.style.blend =
                !splats.marks.isCombined && splats.marks.textureOperator == MarkOperator::Blend;
            for (int channel = 0; channel < 3; ++channel) {
                batch.style.blendColor[channel] = splats.marks.blendColor[channel];
            }
        }
        if (footprint.shape != SplatShape::VectorMarks) {
            batch.sampler = cache.footprint(splats.footprint);
            // A radial footprint is 0 beyond its reach: the pixel boxes bound that disc.
            const float discRadius =
                batch.sampler->isRadial ? std::sqrt(batch.sampler->reach) : 0.0f;
            auto setup =
                std::make_unique<SplatSetup>(splats.view, static_cast<float>(footprint.extent),
                                             frame.width, frame.height, discRadius);
            setup->setStamps(cache.stamps(splats.footprint, *setup));
            batch.setup = std::move(setup);
        }
        batches.push_back(std::move(batch));
    }
    return batches;
}

// The rasters of marks [first, first + count) of `batch`, and their rows, in parallel.
void setUpMarks(const PreparedBatch& batch, const Frame& frame, std::size_t first,
                std::size_t count, std::vector<MarkRaster>& rasters, std::vector<RowSpan>& rows) {
    rasters.resize(std::max(rasters.size(), count));
    rows.resize(std::max(rows.size(), count));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t i = range.begin(); i < range.end(); ++i) {
                              rasters[i] =
                                  markRaster(batch.marks[first + i], frame.width, frame.height);
                              rows[i] = {rasters[i].rowBegin, rasters[i].rowEnd};
                          }
                      });
}

} // namespace

CpuRenderer::CpuRenderer(int threads)
    : mThreads(threads > 0 ? threads
                           : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))),
      mSamplers(std::make_unique<detail::SamplerCache>()) {}

CpuRenderer::~CpuRenderer() = default;
CpuRenderer::CpuRenderer(CpuRenderer&&) noexcept = default;
CpuRenderer& CpuRenderer::operator=(CpuRenderer&&) noexcept = default;

std::string CpuRenderer::description() const {
    return std::string("CPU (") + compositeTarget() + ", " + std::to_string(mThreads) +
           (mThreads == 1 ? " thread)" : " threads)");
}

void CpuRenderer::releasePlanes() { mPlanes.reset(); }

image::Image CpuRenderer::draw(const Frame& frame, sg::RenderStatistics& statistics,
                               bool withDepth) const {
    Clock::time_point start = Clock::now();
    const std::vector<PreparedBatch> batches = prepareBatches(frame, *mSamplers);
    const bool withMeshDepth = !frame.meshes.empty();
    std::optional<image::Image> readBack; // the image, where the draw has read it back
    const Bands bands(frame.height, mThreads);
    // More threads than the hardware has would only wait for each other (and oneTBB warns);
    // the bands still follow mThreads, which changes nothing in the image.
    tbb::task_arena arena(
        std::min(mThreads, static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))));
    // The planes are cleared by the arena's threads (ColorPlanes::clear()), a new object's pages
    // faulted in by all of them.
    arena.execute([&] {
        if (mPlanes && mPlanes->width() == frame.width && mPlanes->height() == frame.height &&
            mPlanes->hasDepth() == withMeshDepth) {
            mPlanes->clear(frame.background);
        } else {
            mPlanes.reset();
            mPlanes = std::make_unique<ColorPlanes>(frame.width, frame.height, frame.background,
                                                    withMeshDepth);
        }
    });
    ColorPlanes& planes = *mPlanes;
    arena.execute([&] {
        if (!frame.meshes.empty()) {
            const MeshRasterizer meshes(frame.meshes, frame.width, frame.height);
            tbb::parallel_for(0, bands.count, [&](int band) {
                meshes.draw(planes, bands.begin(band), bands.end(band, frame.height));
                for (int row = bands.begin(band);
                     frame.meshesHideOnly && row < bands.end(band, frame.height); ++row) {
                    std::fill_n(planes.red(row), frame.width, frame.background.r);
                    std::fill_n(planes.green(row), frame.width, frame.background.g);
                    std::fill_n(planes.blue(row), frame.width, frame.background.b);
                    std::fill_n(planes.alpha(row), frame.width, frame.background.a);
                }
            });
        }
        if (frame.splats.size() == 1 && frame.splats.front().voxels && batches.front().setup &&
            batches.front().setup->stamps() != nullptr) {
            // One batch of voxels, stamped: band by band through every slice, no list.
            const PreparedBatch& batch = batches.front();
            const VoxelRaster voxels(*batch.splats->voxels, *batch.setup, *batch.sampler,
                                     frame.width, frame.height);
            const VoxelBands voxelBands(voxels.rowRange(), mThreads);
            // Each band is copied into the image as soon as it is drawn, by its thread, while
            // its rows are in that core's caches; the rows no band covers as two more pieces.
            // A read-back after the bands would be one thread's pass over the whole image (and
            // the image is not cleared first: the pieces write all of it).
            readBack.emplace(image::Image::uncleared(frame.width, frame.height));
            if (withDepth) {
                readBack->addDepth(1.0f);
            }
            tbb::parallel_for(
                tbb::blocked_range<int>(0, voxelBands.count + 2, 1),
                [&](const tbb::blocked_range<int>& range) {
                    for (int piece = range.begin(); piece < range.end(); ++piece) {
                        if (piece < voxelBands.count) {
                            compositeVoxels(voxels, planes, voxelBands.begin(piece),
                                            voxelBands.end(piece));
                            planes.copyRows(*readBack, voxelBands.begin(piece),
                                            voxelBands.end(piece), withDepth);
                        } else if (piece == voxelBands.count) {
                            planes.copyRows(*readBack, 0, voxelBands.first, withDepth);
                        } else {
                            planes.copyRows(*readBack, voxelBands.last, frame.height,
                                            withDepth);
                        }
                    }
                });
            return;
        }
        // The splats of all batches in one depth order, as GlRenderer draws them.
        const std::vector<render::detail::SplatRun> runs =
            render::detail::frameRuns(frame, statistics);
        std::vector<SplatRaster> rasters(kChunk);
        std::vector<RowSpan> rows(kChunk);
        std::vector<MarkRaster> markRasters;
        std::vector<RowSpan> markRows;
        std::vector<std::uint32_t> markBegins;
        // Composites splats [first, first + count) of `list` of `batch` (set up in chunks).
        const auto compositeList = [&](const PreparedBatch& batch, const octree::SplatList& list,
                                       std::size_t first, std::size_t end) {
            const octree::Splat* splats = list.splats().data();
            for (std::size_t chunk = first; chunk < end; chunk += kChunk) {
                const std::size_t count = std::min(kChunk, end - chunk);
                tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024),
                                  [&](const tbb::blocked_range<std::size_t>& range) {
                                      batch.setup->setUp(splats + chunk + range.begin(),
                                                         range.size(),
                                                         rasters.data() + range.begin());
                                      for (std::size_t i = range.begin(); i < range.end(); ++i) {
                                          rows[i] = rowSpanOf(rasters[i]);
                                      }
                                  });
                // Combined splats: each splat's marks right after it.
                std::optional<FollowingMarks> following;
                if (list.hasMarks()) {
                    const std::size_t marksFirst = list.markBegin(chunk);
                    setUpMarks(batch, frame, marksFirst, list.markBegin(chunk + count) - marksFirst,
                               markRasters, markRows);
                    markBegins.resize(count + 1);
                    for (std::size_t i = 0; i <= count; ++i) {
                        markBegins[i] =
                            static_cast<std::uint32_t>(list.markBegin(chunk + i) - marksFirst);
                    }
                    following = FollowingMarks{markRasters.data(), markRows.data(),
                                               markBegins.data(), batch.style};
                }
                tbb::parallel_for(0, bands.count, [&](int band) {
                    compositeSplats(rasters.data(), rows.data(), count, batch.sampler.get(),
                                    batch.setup->stamps(), following ? &*following : nullptr,
                                    planes, bands.begin(band), bands.end(band, frame.height));
                });
            }
        };
        for (const render::detail::SplatRun& run : runs) {
            const PreparedBatch& batch = batches[run.batch];
            if (batch.splats->voxels && runs.size() == 1) {
                // One batch of voxels, not stamped (perspective, another footprint): listed a
                // few slices at a time, never whole.
                const octree::VoxelSplats& voxels = *batch.splats->voxels;
                const octree::SliceOrder& order = voxels.order();
                const glm::u64vec3 dims = voxels.grid().dims();
                const std::uint64_t sliceVoxels = dims[order.axes()[1]] * dims[order.axes()[2]];
                const std::size_t step = static_cast<std::size_t>(std::max<std::uint64_t>(
                    1, 4 * kChunk / std::max<std::uint64_t>(sliceVoxels, 1)));
                octree::SplatList slices;
                for (std::size_t slice = 0; slice < order.sliceCount(); slice += step) {
                    octree::emitVoxelSplats(order, voxels.drawn(), slice,
                                            std::min(slice + step, order.sliceCount()), slices);
                    compositeList(batch, slices, 0, slices.size());
                }
                continue;
            }
            const octree::SplatList& list = *batch.splats->list();
            if (!batch.setup) {
                // Marks only: their own chunks, in the list's order.
                const std::size_t end = list.markBegin(run.end);
                for (std::size_t chunk = list.markBegin(run.begin); chunk < end; chunk += kChunk) {
                    const std::size_t count = std::min(kChunk, end - chunk);
                    setUpMarks(batch, frame, chunk, count, markRasters, markRows);
                    tbb::parallel_for(0, bands.count, [&](int band) {
                        compositeMarks(markRasters.data(), markRows.data(), count, batch.style,
                                       planes, bands.begin(band), bands.end(band, frame.height));
                    });
                }
                continue;
            }
            compositeList(batch, list, run.begin, run.end);
        }
    });
    statistics.addTime(sg::RenderPhase::Draw, secondsSince(start));
    if (readBack) {
        return std::move(*readBack);
    }
    start = Clock::now();
    image::Image image = planes.toImage(withDepth);
    statistics.addTime(sg::RenderPhase::ReadBack, secondsSince(start));
    return image;
}

} // namespace texsplat::render::cpu
