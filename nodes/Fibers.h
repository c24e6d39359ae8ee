#pragma once

#include "nodes/TriangleMesh.h"
#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/actions/State.h"
#include "scenegraph/fields/Fields.h"

namespace texsplat::nodes {

/// @brief The fibers of the current VolumeData (source AEROGEL) as closed polygon cylinders,
/// drawn opaque inside the volume rendering as in the paper's Figure 7; coloured by the current
/// Material's diffuse colour. Other sources have no fibers: the node then draws nothing.
///
/// File format:
/// @code
/// Fibers {
///     segments  12
/// }
/// @endcode
class Fibers : public sg::Declare<Fibers, sg::Node> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "Fibers";

    sg::SFInt32 segments; ///< sides of each cylinder, >= 3

    /// @brief The cylinders of the state's VolumeData (see fiberMesh()).
    /// @throws DataError when there is no VolumeData before this node or `segments` is below 3;
    /// what loading the volume throws.
    TriangleMesh triangleMesh(sg::State& state) const;

    /// @brief Extends the action's box by the cylinders.
    void getBoundingBox(sg::BoundingBoxAction& action) override;

protected:
    Fibers();
};

} // namespace texsplat::nodes
