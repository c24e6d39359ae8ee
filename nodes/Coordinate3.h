#pragma once

#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"

namespace texsplat::nodes {

/// @brief Vertex positions for the IndexedFaceSet nodes that follow (Inventor's Coordinate3):
/// puts itself into Coordinate3Element.
///
/// File format:
/// @code
/// Coordinate3 {
///     point  0 0 0
/// }
/// @endcode
class Coordinate3 : public sg::Declare<Coordinate3, sg::Node> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "Coordinate3";

    sg::MFVec3f point; ///< the positions, local space

    /// @brief Puts this node into Coordinate3Element.
    void doAction(sg::Action& action) override;

protected:
    Coordinate3();
};

} // namespace texsplat::nodes
