#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace texsplat::sg {

/// @brief The steps a frame spends its time in, as `texsplat render --time-report` lists them.
enum class RenderPhase {
    Load,       ///< reading or generating volume data and meshes
    Classify,   ///< transfer function over the grid, octree build
    Order,      ///< back-to-front splat list for the view (slice order or octree cut)
    Upload,     ///< buffers and textures to GL (GL backend)
    Draw,       ///< both passes, until the GL finished them (glFinish) or the CPU rasterized them
    ReadBack,   ///< framebuffer (or the CPU backend's colour planes) to an image
};

/// @brief Number of RenderPhase values.
inline constexpr std::size_t kRenderPhaseCount = 6;

/// @brief Lower-case name of a phase ("read back"), for reports.
std::string_view toString(RenderPhase phase);

/// @brief Bytes a frame's drawing keeps, per kind, as `texsplat render --time-report` lists
/// them: measured from the objects, so that what a scene does not use shows as 0 (a
/// full-resolution frame builds no octree, the CPU backend makes no textures). Each splat node
/// adds what it reads and makes; a grid that two nodes read counts twice.
struct FrameMemory {
    std::uint64_t grids = 0;      ///< the volume grids the splat nodes read
    std::uint64_t classified = 0; ///< the classified grids (octree::ClassifiedGrid)
    std::uint64_t octree = 0;     ///< the octrees' node records
    std::uint64_t splats = 0;     ///< the splat lists
    std::uint64_t textures = 0;   ///< GL textures of the splat batches (footprints, vector tables)

    /// @brief Keeps the larger of each count: the largest frame of an animation.
    void keepLarger(const FrameMemory& other);
};

/// @brief What the splat nodes and the backend made during a frame rather than kept from an
/// earlier one: a transfer-function edit classifies again (and builds a new octree for a cut) but
/// makes no new value ranges, which follow the data alone.
struct FrameBuilds {
    std::size_t valueRanges = 0;     ///< block value ranges of a grid (octree::ValueRanges)
    std::size_t classifications = 0; ///< classified grids
    std::size_t octrees = 0;         ///< octrees over a classified grid
    std::size_t valueHistograms = 0; ///< block value histograms of a grid, for previews
    std::size_t previews = 0;        ///< previews of a transfer-function edit (block means)
    std::size_t splatBatches = 0;    ///< GL splat batches (shaders, footprint textures)

    /// @brief Adds another frame's counts.
    FrameBuilds& operator+=(const FrameBuilds& other);
};

/// @brief Where one frame's time went and how much it drew.
struct RenderStatistics {
    std::array<double, kRenderPhaseCount> seconds{}; ///< wall seconds per RenderPhase
    std::size_t splats = 0;    ///< splats drawn (instances)
    std::size_t triangles = 0; ///< opaque triangles drawn (splat quads not counted)
    std::size_t previewed = 0; ///< splat nodes that drew a preview of a transfer-function edit
    FrameMemory memory;        ///< bytes the frame's drawing keeps
    FrameBuilds builds;        ///< what the frame made rather than kept

    /// @brief Seconds spent in `phase`.
    double time(RenderPhase phase) const { return seconds[static_cast<std::size_t>(phase)]; }

    /// @brief Adds `wallSeconds` to `phase`.
    void addTime(RenderPhase phase, double wallSeconds);

    /// @brief Adds another frame's times and counts (totals over an animation); memory keeps
    /// the larger frame's.
    RenderStatistics& operator+=(const RenderStatistics& other);
};

} // namespace texsplat::sg
