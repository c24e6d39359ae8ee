#pragma once

namespace texsplat::nodes {

class VolumeData;

/// @brief State element: the VolumeData met last (Inventor style: like coordinates, the data a
/// following shape uses). The splat nodes that follow render it, placed by their own model
/// matrix.
struct VolumeElement {
    /// @brief The volume, or nullptr before any (non-owning: valid during the traversal).
    const VolumeData* volume = nullptr;
};

} // namespace texsplat::nodes
