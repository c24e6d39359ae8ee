#pragma once

/// @file
/// @brief Forward declarations of the octree library (namespace texsplat::octree).

namespace texsplat::octree {

class ClassifiedGrid;
class Cut;
class Octree;
class Refiner;
class SliceOrder;
class SplatList;
class ValueHistograms;
class ValueRanges;
class View;
struct NodeRef;
struct OctreeNode;
struct RefineBudget;
struct Splat;
struct SplatVector;

} // namespace texsplat::octree
