#pragma once

#include "nodes/bench/FlowLegibility.h"
#include "nodes/render/BackendChoice.h"
#include "nodes/render/MarkDrawing.h"
#include "scenegraph/Node.h"

#include <string>
#include <vector>

namespace texsplat::bench {

/// @brief The planar fields the legibility bench draws (z-invariant, seen face-on).
enum class LegibilityField {
    Vortex,  ///< (−y, x, 0) about the grid's centre: curved streaks, speed growing outwards
    Saddle,  ///< (x, −y, 0) about the centre: inflow along y, outflow along x
    Uniform, ///< (cos a, sin a, 0): straight streaks at the angle a
};

/// @brief One case of the legibility bench.
struct LegibilityCase {
    LegibilityField field = LegibilityField::Vortex;
    float angle = 30.0f; ///< Uniform: the flow's angle in degrees, counter-clockwise
    render::MarkType type = render::MarkType::Scratches;
    render::Backend backend = render::Backend::Cpu;
    float pixelsPerVoxel = 4.0f; ///< the zoom
    int voxels = 32;             ///< the grid is voxels³, spacing 1
};

/// @brief What the legibility bench measured of one case (docs/results.md, "Legibility of
/// vector marks").
struct LegibilityResult {
    LegibilityCase what;
    StreakAngles marks;        ///< the vector splats' image against the field
    StreakAngles reference;    ///< a line integral convolution of the same field, same measure
    double skew = 0.0;         ///< downstreamSkew(): > 0 when the marks point downstream
    double orientation = 0.0;  ///< Uniform: streakOrientation() of the image, degrees
    double frameSeconds = 0.0; ///< median of the timed frames
    int width = 0;             ///< image pixels (square)
};

/// @brief The scene of `what`: an orthographic camera looking down −z at the grid with two
/// voxels of margin, the default TransferFunction (opacity rising with the magnitude over the
/// data's range), the field as a VolumeData, and `VectorSplat { colorMode CONSTANT color 1 1 1
/// markType … }`. The image is `(voxels + 4) · pixelsPerVoxel` pixels square. Registers the node
/// types (nodes::registerNodeTypes()).
sg::Node::Ptr legibilityScene(const LegibilityCase& what);

/// @brief The field's direction at pixel (x, y) of the case's image (y down); zero at the centre
/// of a vortex or saddle.
ImageFlow legibilityFlow(const LegibilityCase& what);

/// @brief How measureLegibility() measures.
struct LegibilityOptions {
    int repeat = 3;        ///< timed frames after one untimed (0: the untimed one alone)
    bool reference = true; ///< also measure the line integral convolution of the field
    std::string imagePath; ///< where to write the image too ("" not at all)
};

/// @brief Measures `what`: renders it (the GL backend needs a current context), and measures its
/// streak angles over the grid's inside less two voxels at each side (and, for a vortex or
/// saddle, the two voxels about the centre, where the direction is not defined), smoothed over
/// half a voxel on screen; the line integral convolution of the same field (streamlines 2.5
/// voxels and 4 pixels long each way) on the same pixels; the downstream skew; and for a uniform
/// field the image's streak orientation.
LegibilityResult measureLegibility(const LegibilityCase& what,
                                   const LegibilityOptions& options = {});

/// @brief The cases `texsplat bench --legibility` measures on each of `backends`: the vortex and
/// the saddle at 4, 6, 10 and 16 pixels per voxel, and uniform fields at 0°, 30°, 60°, 90° and
/// 135° at 4 and 16, each with both mark types.
std::vector<LegibilityCase> legibilityCases(const std::vector<render::Backend>& backends);

/// @brief A file name for the image of `what`, e.g. "vortex-scratches-cpu-4.png",
/// "uniform30-particles-gl-16.png".
std::string legibilityImageName(const LegibilityCase& what);

/// @brief The rows as a text table, one per case: legibilityTableHeader() and a
/// legibilityTableRow() per row.
std::string legibilityTable(const std::vector<LegibilityResult>& rows);
/// @brief The table's column names, one line.
std::string legibilityTableHeader();
/// @brief One row of the table, one line (for progress while the cases are measured).
std::string legibilityTableRow(const LegibilityResult& row);

} // namespace texsplat::bench
