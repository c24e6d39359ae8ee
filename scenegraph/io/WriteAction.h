#pragma once

#include "scenegraph/actions/Action.h"
#include "scenegraph/fields/FieldValueWriter.h"

#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

namespace texsplat::sg {

/// @brief Writes a graph as an Open Inventor ASCII file that SceneReader (and Coin, and other
/// Inventor readers) read back into the same graph.
///
/// Each node is written from its type's field declaration: only fields that are not default
/// (or are connected); children for groups. A node or engine referenced more than once gets a
/// DEF name at its first appearance and USE afterwards: its own name, or `+N` (Coin's form for
/// an unnamed shared node; readers strip it again) when it has none, with `+N` appended when
/// two written containers share a name. Named nodes are always written with DEF so that names
/// survive. Types that Inventor itself does not define (our extension nodes, UnknownNode)
/// describe their fields, `fields [ SFFloat size, … ]` (engines: `inputs [ … ] outputs [ … ]`),
/// so other Inventor readers can parse and pass them through. Connections are written as
/// `field = Engine { … } . output` or `field = USE name . field`, with the source in place where
/// it is not written before, also when it is outside the scene (the reader makes the connection
/// hold such a source, so the connection survives).
///
/// The action registers one method, for Node::classType(), that writes any node; its
/// traversal depth limit (Action::kMaxDepth) bounds the nesting.
class WriteAction : public Action, private FieldValueWriter {
public:
    /// @brief A writer to `output` (header and graph are written by apply()).
    explicit WriteAction(std::ostream& output);

    /// @brief The table of this action: `Node` → write the node.
    static MethodTable& methods();

    /// @brief The file text for the graph under `root`.
    static std::string writeString(Node& root);

    /// @brief Writes the graph under `root` to `path` atomically (a temporary file renamed over
    /// `path`). Throws IoError when the file cannot be written.
    static void writeFile(Node& root, const std::string& path);

protected:
    /// @brief Counts references (for DEF names) and writes the header.
    void beginTraversal(Node& root) override;

    /// @brief True: a shared node is written once, then referred to with USE.
    bool visitsSharedNodesOnce() const override { return true; }

private:
    void writeNodeMethod(Node& node);
    void writeContainer(FieldContainer& container);
    void writeDescriptions(FieldContainer& container);
    void writeFieldEntry(const Field& field);
    void writeReference(FieldContainer& container);
    std::string definitionName(const FieldContainer& container);
    void write(std::string_view text);
    void newLine();

    void writeToken(std::string_view text) override;
    void writeNode(const std::shared_ptr<Node>& node) override;
    void beginList() override;
    void endList() override;

    std::ostream& mOutput;
    int mIndent = 0;
    std::size_t mColumn = 0;
    std::size_t mEngineNesting = 0;
    // The multi-value list being written; a node inside a list saves and restores it, since
    // its own fields may hold lists too.
    struct ListState {
        bool isOpen = false;
        bool hasNodes = false;
        std::size_t count = 0;
    };
    ListState mList;
    std::unordered_map<const FieldContainer*, std::size_t> mReferenceCounts;
    std::unordered_map<const FieldContainer*, std::string> mWritten;
    std::unordered_set<std::string> mUsedNames;
    std::size_t mNextAutomaticName = 0;
};

} // namespace texsplat::sg
