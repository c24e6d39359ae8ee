#pragma once

/// @file
/// @brief Forward declarations of the octree library (namespace texsplat::octree).

namespace texsplat::octree {

class ClassifiedGrid;
class Cut;
class DrawnVoxels;
class MarkSource;
class Octree;
class Refiner;
class SliceOrder;
class SplatList;
class ValueHistograms;
class ValueRanges;
class View;
class VoxelShadows;
class VoxelSplats;
struct NodeRef;
struct OctreeNode;
struct RefineBudget;
struct Splat;
struct SplatMark;

} // namespace texsplat::octree
