#pragma once

#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"
#include "nodes/volume/Progress.h"

#include <string>
#include <vector>

namespace texsplat::volume {

/// @brief One grid of an OpenVDB file, as listVdbGrids() describes it.
struct VdbGridInfo {
    /// @brief The grid's name in the file ("density").
    std::string name;
    /// @brief OpenVDB's name of its value type ("float", "vec3s", "bool", ...).
    std::string valueType;
};

/// @brief Whether this build reads OpenVDB files (CMake option TEXSPLAT_WITH_OPENVDB).
bool isOpenVdbAvailable();

/// @brief The grids an OpenVDB file holds, in the order OpenVDB lists them (by name).
/// @throws IoError when the file cannot be opened or is not an OpenVDB file, or when texsplat
/// was built without OpenVDB.
std::vector<VdbGridInfo> listVdbGrids(const std::string& path);

/// @brief Reads the grid named `gridName` from an OpenVDB file into a SparseGrid, so that sparse
/// data stays sparse in memory: a `float` grid gives a ScalarGrid, a `vec3s` grid a VectorGrid.
///
/// The grid's index space starts at the low corner of its active voxels' bounding box, which
/// becomes voxel (0,0,0); OpenVDB's leaf nodes map one to one onto SparseGrid blocks. Active
/// tiles are expanded into voxels. NaN or infinite active values become empty voxels, reported
/// in one warning through texsplat::log. `progress` is called with "reading grid '<name>'"
/// before OpenVDB reads the grid, then with "copying grid '<name>'" as voxels are copied; it may
/// cancel.
/// @throws IoError when the file cannot be opened or read (or OpenVDB is not built in);
/// DataError when no grid has that name (the message lists the grids the file has), when the
/// grid holds another value type, has no active voxels, has only NaN or infinite active voxels,
/// or has a transform other than an axis-aligned scale and translation; LoadCancelled when
/// `progress` answered false.
AnyGrid readVdbGrid(const std::string& path, const std::string& gridName,
                    const ProgressCallback& progress = {});

/// @brief The geometry readVdbGrid() gives the grid named `gridName`, from its metadata (the
/// active voxels' box OpenVDB writes with each grid, `file_bbox_min` and `file_bbox_max`) and
/// transform, without reading its tree.
/// @throws as readVdbGrid(); DataError for a grid without that metadata.
GridGeometry vdbGridGeometry(const std::string& path, const std::string& gridName);

/// @brief readVdbGrid() of the voxels of `region` only (a box of that grid's voxels, not empty: a
/// brick of a render split over processes), placed where they lie: OpenVDB reads the tree's
/// topology and only the leaves that meet the region's box. The brick's active voxels may be
/// none, and are not checked for finite values.
/// @throws as vdbGridGeometry() and readVdbGrid(); DataError for a region outside the grid.
AnyGrid readVdbRegion(const std::string& path, const std::string& gridName, const IndexBox& region,
                      const ProgressCallback& progress = {});

} // namespace texsplat::volume
