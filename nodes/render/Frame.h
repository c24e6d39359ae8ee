#pragma once

#include "nodes/render/MarkDrawing.h"
#include "nodes/render/MeshLighting.h"
#include "nodes/render/SplatFootprint.h"
#include "nodes/render/SplatView.h"
#include "octree/Fwd.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <vector>

namespace texsplat::nodes {
struct TriangleMesh;
} // namespace texsplat::nodes

namespace texsplat::render {

/// @brief An opaque mesh of a frame: its triangles in the producing node's local space and how
/// they are placed and lit.
struct FrameMesh {
    std::shared_ptr<const nodes::TriangleMesh> mesh; ///< the triangles
    MeshLighting lighting;                           ///< matrices, lights, emissive colour
};

/// @brief One splat node's contribution to a frame: its splats back to front for the view, and
/// what each looks like.
///
/// The splats come as a list (`splats`: an octree cut, vector and combined splats with their
/// marks) or, for a full-resolution frame of a grid, as the grid's voxels in slice order
/// (`voxels`), which a backend may draw without listing them (docs/design.md, "Splat lists and
/// voxel batches"); list() gives either as a list.
struct FrameSplats {
    std::shared_ptr<const octree::SplatList> splats;   ///< back to front, or null: `voxels`
    std::shared_ptr<const octree::VoxelSplats> voxels; ///< every voxel's splat, or null
    SplatView view;                                    ///< how the batch is seen (local space)
    std::shared_ptr<const SplatFootprint> footprint; ///< shape, kernel texture, mark table
    MarkDrawing marks;                               ///< vector and combined splats only
    glm::mat4 localToCamera{1.0f};                   ///< view · model

    /// @brief The splats as a list: `splats`, or the voxels' list (made on first use).
    const std::shared_ptr<const octree::SplatList>& list() const;

    /// @brief Number of splats.
    std::size_t splatCount() const;

    /// @brief How far each splat is from the eye, what batches of several nodes are merged by:
    /// the depth along the view (camera space looks down −z) for an orthographic camera, the
    /// distance from the eye for a perspective one.
    std::vector<float> cameraDepths() const;
};

/// @brief A frame as every backend draws it (docs/design.md, "Data flow of one frame"): the size
/// and background, the opaque meshes, and the splat batches of the splat nodes in traversal order.
/// Splats are depth-tested against the meshes without writing depth and composited with
/// premultiplied "over", batches of several nodes merged into one depth order.
struct Frame {
    int width = 1;                  ///< pixels
    int height = 1;                 ///< pixels
    glm::vec4 background{0.0f};     ///< premultiplied clear colour
    std::vector<FrameMesh> meshes;  ///< opaque, in traversal order
    std::vector<FrameSplats> splats; ///< one entry per splat node traversal
    /// @brief Whether the meshes only hide the splats behind them and draw no colour (the
    /// background stays where they are): the frames of a render split over processes, whose
    /// meshes one image draws under all the bricks' splats (nodes/distributed).
    bool meshesHideOnly = false;
};

} // namespace texsplat::render
