#pragma once

#include "scenegraph/Node.h"

#include <vector>

namespace texsplat::nodes {

class ScalarSplat;
class TransferFunction;
class VolumeData;

/// @brief What one splat node reads where it is traversed: the TransferFunction and the
/// VolumeData in effect there.
struct SplatInput {
    const TransferFunction* transfer = nullptr;
    const VolumeData* volume = nullptr;
    const ScalarSplat* splat = nullptr; ///< the splat node itself
};

/// @brief The inputs of each splat node (ScalarSplat and its kinds) under `root` that has both a
/// transfer function and a volume, in traversal order (a USEd node once per path). The pointers
/// are the scene's nodes: valid while the scene holds them. Which function classifies which
/// volume is a matter of traversal state (figure 8 of the paper has two of each), so a legend
/// or an editor asks this rather than pairing the first of each.
std::vector<SplatInput> splatInputs(sg::Node& root);

} // namespace texsplat::nodes
