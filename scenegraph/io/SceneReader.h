#pragma once

#include "scenegraph/Fwd.h"
#include "scenegraph/io/DataRoots.h"

#include <memory>
#include <string>
#include <string_view>

namespace texsplat::sg {

/// @brief Reads Open Inventor ASCII scene files (`#Inventor V2.1 ascii`) into a node graph.
///
/// The syntax is Inventor's: `#` comments; nodes as `Type { fields… children… }`;
/// `DEF name` / `USE name` (a USEd node is the same shared node, not a copy); field values as
/// each field type defines them (`[ … ]` lists, a single MF value without brackets);
/// connections `field = Engine { … } . output` and `field = USE name . field` (a connection
/// holds a source that nothing else in the scene holds, such as a node written in place; chains
/// of connections may be Field::kMaxConnectionChain links long). Types come from
/// the NodeRegistry; a node of an unregistered type is read when it describes itself
/// (`fields [ SFFloat size ]`) and becomes an UnknownNode that writes back identically.
///
/// Every problem throws ParseError naming file, line, column and what was expected, e.g.
/// `scene.iv:12:5: expected '}' to close Separator opened at 3:1`; nothing of the graph is
/// returned then. A file with several top-level nodes is read as a Separator holding them.
class SceneReader {
public:
    /// @brief How a scene is read.
    struct ReadOptions {
        /// @brief The folders every file the scene's nodes read must lie in (docs/security.md):
        /// given to each node that reads files (RelativeFileNames::setDataRoots()). Null: any
        /// file its user can read, as a scene file one wrote oneself may.
        std::shared_ptr<const DataRoots> dataRoots;
    };

    /// @brief Reads the file at `path`. Throws IoError when it cannot be read, ParseError when
    /// its content is not a valid scene. Nodes that read files (RelativeFileNames) resolve
    /// relative names against the folder of `path`.
    static std::shared_ptr<Node> readFile(const std::string& path,
                                          const ReadOptions& options = {});

    /// @brief Reads scene text; `fileName` names it in messages. Relative file names in the
    /// scene stay relative to the working directory.
    static std::shared_ptr<Node> readString(std::string_view text,
                                            const std::string& fileName = "<string>",
                                            const ReadOptions& options = {});
};

} // namespace texsplat::sg
