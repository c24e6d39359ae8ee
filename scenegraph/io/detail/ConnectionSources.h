#pragma once

#include "scenegraph/Fwd.h"
#include "scenegraph/io/detail/SceneLexer.h"

#include <memory>
#include <vector>

namespace texsplat::sg::detail {

/// @brief A field-to-field connection read from a file (`size = USE box . size`,
/// `size = TestCube { size 2 } . size`): its source container may be held by nothing else.
struct ReadConnection {
    Field* field = nullptr;
    /// Holds the connected field's container until the read ends: a later value in the file may
    /// drop it from the scene (`node Holder { a = Src { } . b } node NULL`).
    std::shared_ptr<FieldContainer> fieldContainer;
    /// Holds the source's container until keepUnheldSources() has decided who holds it.
    std::shared_ptr<FieldContainer> source;
    /// Where the source starts in the file (`USE`, `DEF` or its type name).
    SourceLocation where;
};

/// @brief Makes each connection whose source's container nothing in the graph under `root`
/// holds keep that container alive (Field::keepSourceAlive()), as a connection keeps its
/// engine, so that connections survive the read. A connection does not keep a container that
/// contains the connected field's container, directly or through others (counting the other
/// connections that might keep their sources), since that could make a cycle of shared
/// pointers. Connections replaced later in the file are left alone. Returns the first
/// connection whose source stays unheld for that reason, or nullptr. Takes time linear in the
/// size of the graph.
const ReadConnection* keepUnheldSources(Node& root, const std::vector<ReadConnection>& connections);

} // namespace texsplat::sg::detail
