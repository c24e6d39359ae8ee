#pragma once

namespace texsplat::nodes {

class Coordinate3;

/// @brief State element: the Coordinate3 met last, whose points the following IndexedFaceSet
/// indexes (Inventor's coordinate element).
struct Coordinate3Element {
    /// @brief The coordinates, or nullptr before any (non-owning: valid during the traversal).
    const Coordinate3* coordinates = nullptr;
};

} // namespace texsplat::nodes
