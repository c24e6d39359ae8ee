#pragma once

#include "nodes/TriangleMesh.h"
#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/io/RelativeFileNames.h"

#include <memory>
#include <mutex>

namespace texsplat::nodes {

/// @brief Polygon geometry from a glTF 2.0 file (`.gltf` with embedded or external buffers, or
/// `.glb`), drawn opaque among the splats (paper, Figure 7: polygon fibers inside the volume).
///
/// The file is read on first use (triangleMesh(), a bounding box) and cached until `fileName`
/// changes. The meshes of the default scene are merged with their nodes' transforms applied;
/// normals are computed when the file has none; each primitive takes its material's base colour.
/// Errors name the node, then the file: "Mesh 'part': part.gltf: not a readable glTF 2.0 file:
/// <tinygltf's message>" (ParseError), "... cannot open file (...)" (IoError).
///
/// File format:
/// @code
/// Mesh {
///     fileName  ""
/// }
/// @endcode
class Mesh : public sg::Declare<Mesh, sg::Node>, public sg::RelativeFileNames {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "Mesh";

    /// the glTF file (relative to the scene file's folder: sg::RelativeFileNames)
    sg::SFString fileName;

    /// @brief The triangles of the file, read on first use.
    /// @throws IoError, ParseError or DataError (prefixed with the node) when reading fails.
    std::shared_ptr<const TriangleMesh> triangleMesh() const;

    /// @brief Whether the file is read now (the cache holds it).
    bool isLoaded() const;

    /// @brief Extends the action's box by the triangles' bounds.
    void getBoundingBox(sg::BoundingBoxAction& action) override;

    /// @brief Drops the cached triangles, then notifies as every node does.
    void notify(const sg::Field* source) override;

protected:
    Mesh();

private:
    mutable std::mutex mMutex;
    mutable std::shared_ptr<const TriangleMesh> mMesh;
};

} // namespace texsplat::nodes
