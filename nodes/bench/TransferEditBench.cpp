#include "nodes/bench/TransferEditBench.h"

#include "nodes/ScalarSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/image/ImageComparison.h"
#include "nodes/image/ImageIo.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/volume/ValueHistogram.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Octree.h"
#include "octree/ValueRanges.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/SearchAction.h"

#include <chrono>
#include <cstdio>
#include <iterator>
#include <limits>
#include <optional>

namespace texsplat::bench {
namespace {

using Clock = std::chrono::steady_clock;

template <class T> std::vector<T*> nodesOf(sg::Node& root) {
    sg::SearchAction search;
    search.setType(T::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.apply(root);
    std::vector<T*> found;
    for (const sg::Path& path : search.paths()) {
        found.push_back(&static_cast<T&>(*path.tail()));
    }
    return found;
}

struct Edit {
    const char* name;
    const char* fileName; // in the names of the images written
    void (*apply)(nodes::TransferFunction&);
};

void halveOpacities(nodes::TransferFunction& transfer) {
    std::vector<float> opacities = transfer.opacities.values();
    for (float& opacity : opacities) {
        opacity *= 0.5f;
    }
    transfer.opacities.setValue(std::move(opacities));
}

void raiseRangeMinimum(nodes::TransferFunction& transfer) {
    const glm::vec2 range = transfer.range.value();
    transfer.rangeMode.setValue(nodes::RangeMode::Fixed);
    transfer.range.setValue(glm::vec2(range.x + 0.3f * (range.y - range.x), range.y));
}

constexpr Edit kEdits[] = {{"opacities x 0.5", "opacities-half", halveOpacities},
                           {"range from 30 %", "range-from-30", raiseRangeMinimum}};

std::string imagePath(const std::string& folder, const Edit& edit, std::uint64_t budget,
                      const std::string& kind) {
    return folder + "/" + edit.fileName + "-" + (budget == 0 ? "full" : std::to_string(budget)) +
           "-" + kind + ".png";
}

// A CPU frame of `root`: its wall time less loading, its statistics and image.
struct Timed {
    double seconds = 0.0;
    sg::RenderStatistics statistics;
    image::Image image;
};

Timed timeFrame(sg::Node& root, glm::ivec2 size, const render::cpu::CpuRenderer& renderer,
                bool interactive = false) {
    // Over opaque black, as `texsplat render` draws by default (the images written show it).
    render::FrameAction action(size.x, size.y, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    action.setInteractive(interactive);
    action.setPreviewMinimumVoxels(0); // the preview is measured whatever the grid's size
    const Clock::time_point start = Clock::now();
    Timed timed{0.0, {}, renderer.draw(action.collect(root), action.statistics(), false)};
    timed.seconds = std::chrono::duration<double>(Clock::now() - start).count() -
                    action.statistics().time(sg::RenderPhase::Load);
    timed.statistics = action.statistics();
    return timed;
}

template <class Step> double secondsOf(Step&& step) {
    const Clock::time_point start = Clock::now();
    step();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The first node of type T in `root`.
template <class T> T& firstOf(sg::Node& root) {
    const std::vector<T*> found = nodesOf<T>(root);
    if (found.empty()) {
        throw DataError(std::string("bench --transfer-edit: the scene has no ") +
                        T::classType().name());
    }
    return *found.front();
}

} // namespace

std::vector<TransferEditTime> measureTransferEdit(const sg::Node::Ptr& scene, glm::ivec2 size,
                                                  const std::vector<std::uint64_t>& maxSplats,
                                                  int threads, const std::string& imageFolder) {
    const render::cpu::CpuRenderer renderer(threads);
    const std::vector<nodes::ScalarSplat*> splatNodes = nodesOf<nodes::ScalarSplat>(*scene);
    nodes::TransferFunction& transfer = firstOf<nodes::TransferFunction>(*scene);
    const nodes::VolumeData& volume = firstOf<nodes::VolumeData>(*scene);
    if (splatNodes.empty()) {
        throw DataError("bench --transfer-edit: the scene has no splat node");
    }
    const std::vector<float> opacities = transfer.opacities.values();
    const glm::vec2 range = transfer.range.value();
    const int rangeMode = transfer.rangeMode.value();
    const auto restore = [&] {
        transfer.opacities.setValue(opacities);
        transfer.range.setValue(range);
        transfer.rangeMode.setValue(rangeMode);
    };
    // The first preview makes the grid's block value histograms, once: not in any row. What
    // the data's summaries cost, once per grid, is timed on its own: the value ranges as a
    // separate walk (the first classification makes them on its way) and the histograms.
    timeFrame(*scene, size, renderer);
    const volume::ScalarGridPtr grid = volume.scalarGrid();
    const double valueRangeSeconds = secondsOf([&] {
        octree::ValueRanges ranges(glm::u64vec3(grid->geometry().dims()));
        grid->forEachActive([&ranges](const glm::i64vec3& index, float value) {
            ranges.add(glm::u64vec3(index), value);
        });
    });
    const double histogramSeconds =
        secondsOf([&] { const auto histograms = volume::blockValueHistograms(*grid); });
    kEdits[0].apply(transfer);
    timeFrame(*scene, size, renderer, true);
    restore();
    std::vector<TransferEditTime> rows;
    std::vector<std::optional<image::Image>> fullResolution(std::size(kEdits));
    for (const std::uint64_t budget : maxSplats) {
        for (std::size_t e = 0; e < std::size(kEdits); ++e) {
            const Edit& edit = kEdits[e];
            for (nodes::ScalarSplat* splat : splatNodes) {
                splat->maxSplats.setValue(static_cast<int>(budget));
            }
            restore();
            timeFrame(*scene, size, renderer); // classifies, builds what the budget needs
            edit.apply(transfer);
            const Timed preview = timeFrame(*scene, size, renderer, true);
            const Timed edited = timeFrame(*scene, size, renderer);
            TransferEditTime row;
            row.previewSeconds = preview.seconds;
            row.previewSplats = preview.statistics.splats;
            if (!imageFolder.empty()) {
                image::writeImage(edited.image, imagePath(imageFolder, edit, budget, "exact"));
                image::writeImage(preview.image, imagePath(imageFolder, edit, budget, "preview"));
            }
            if (budget == 0) {
                fullResolution[e] = edited.image;
            }
            const auto psnr = [&](const image::Image& image) {
                return fullResolution[e]
                           ? image::ImageComparison(*fullResolution[e], image).rgb().psnr
                           : std::numeric_limits<double>::quiet_NaN();
            };
            row.editPsnr = psnr(edited.image);
            row.previewPsnr = psnr(preview.image);
            row.edit = edit.name;
            row.maxSplats = budget;
            row.splats = edited.statistics.splats;
            row.editSeconds = edited.seconds;
            row.editValueRanges = edited.statistics.builds.valueRanges;
            row.reclassifySeconds =
                edited.seconds - edited.statistics.time(sg::RenderPhase::Classify) +
                secondsOf([&] {
                    const std::shared_ptr<const octree::ClassifiedGrid> classified =
                        transfer.classify(*grid);
                    if (budget > 0) {
                        const octree::Octree octree(classified);
                    }
                });
            row.valueRangeSeconds = valueRangeSeconds;
            row.valueHistogramSeconds = histogramSeconds;
            rows.push_back(row);
        }
    }
    return rows;
}

std::string transferEditImagePath(const std::string& imageFolder, const std::string& kind) {
    return imagePath(imageFolder, kEdits[0], 0, kind);
}

std::string transferEditTable(const std::vector<TransferEditTime>& rows) {
    std::string table = "edit              budget     splats   after edit   re-classify all   "
                        "ratio   preview   its splats   dB after edit / preview   "
                        "value ranges, histograms (once)  rebuilt\n";
    for (const TransferEditTime& row : rows) {
        char line[320];
        std::snprintf(line, sizeof line,
                      "%-16s %7s %10zu   %8.3f s   %13.3f s   %5.2f   %5.3f s   %10zu   "
                      "%13.1f / %7.1f   %9.3f s, %9.3f s           %zu\n",
                      row.edit.c_str(),
                      row.maxSplats == 0 ? "full" : std::to_string(row.maxSplats).c_str(),
                      row.splats, row.editSeconds, row.reclassifySeconds,
                      row.reclassifySeconds / row.editSeconds, row.previewSeconds,
                      row.previewSplats, row.editPsnr, row.previewPsnr, row.valueRangeSeconds,
                      row.valueHistogramSeconds, row.editValueRanges);
        table += line;
    }
    return table;
}

} // namespace texsplat::bench
