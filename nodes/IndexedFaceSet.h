#pragma once

#include "nodes/TriangleMesh.h"
#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/actions/State.h"
#include "scenegraph/fields/Fields.h"

#include <glm/glm.hpp>

#include <vector>

namespace texsplat::nodes {

/// @brief Polygons over the points of the current Coordinate3 (Inventor's IndexedFaceSet):
/// `coordIndex` lists each polygon's point indices, counter-clockwise seen from the front, and
/// ends each polygon with -1 (the -1 after the last polygon may be left out).
///
/// Polygons are taken as convex, as Inventor does by default, and split into a fan of
/// triangles; each polygon is shaded flat (its vertices get the polygon's normal, by Newell's
/// method, so slightly non-planar polygons still get a sensible one). The colour is the diffuse
/// colour of the current Material. A polygon with fewer than 3 points, an index below -1 or past
/// the last point throws DataError naming the position in `coordIndex`.
///
/// `materialIndex`, `normalIndex` and `textureCoordIndex` are Inventor's per-face or per-vertex
/// indices into the current materials, normals and texture coordinates. They are read and
/// written, so Inventor files pass through unchanged, but not used by texsplat's renderer (it
/// has one material per shape and computes the normals). Unlike Inventor (`coordIndex 0`), an
/// IndexedFaceSet has no polygons by default; either way nothing is drawn.
///
/// File format:
/// @code
/// IndexedFaceSet {
///     coordIndex         [ ]
///     materialIndex      -1   # not used
///     normalIndex        -1   # not used
///     textureCoordIndex  -1   # not used
/// }
/// @endcode
class IndexedFaceSet : public sg::Declare<IndexedFaceSet, sg::Node> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "IndexedFaceSet";

    sg::MFInt32 coordIndex;        ///< polygons of point indices, each ended by -1
    sg::MFInt32 materialIndex;     ///< Inventor's material indices; read and written, not used
    sg::MFInt32 normalIndex;       ///< Inventor's normal indices; read and written, not used
    sg::MFInt32 textureCoordIndex; ///< Inventor's texture coordinate indices; not used

    /// @brief The triangles of the polygons over `points`, coloured `color`.
    /// @throws DataError for a bad index or a polygon with fewer than 3 points.
    TriangleMesh triangleMesh(const std::vector<glm::vec3>& points, const glm::vec3& color) const;

    /// @brief The triangles over the state's Coordinate3, coloured by its Material.
    /// @throws DataError as above, or when there is no Coordinate3 before this node.
    TriangleMesh triangleMesh(sg::State& state) const;

    /// @brief Extends the action's box by the indexed points.
    void getBoundingBox(sg::BoundingBoxAction& action) override;

protected:
    IndexedFaceSet();

private:
    const std::vector<glm::vec3>& currentPoints(sg::State& state) const;
};

} // namespace texsplat::nodes
