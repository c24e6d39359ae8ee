#pragma once

#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace texsplat::sg {

/// @brief A node with ordered children; actions visit them in order.
///
/// Children are shared: the same node may be a child of several groups, or several times of
/// one. Adding a child that contains this group (directly or deeper) throws DataError, so the
/// graph stays acyclic. Destroying a very deep chain of groups does not recurse.
///
/// File format: `Group { children... }` (no fields).
class Group : public Declare<Group, Node> {
public:
    /// @brief Scene-file name.
    static constexpr const char* kTypeName = "Group";

    ~Group() override;

    /// @brief Appends a child. Throws DataError if `child` is null or would make a cycle.
    void addChild(Node::Ptr child);

    /// @brief Inserts a child before position `index` (<= childCount()). Throws DataError as
    /// addChild(), or on a bad index.
    void insertChild(Node::Ptr child, std::size_t index);

    /// @brief Replaces child `index`. Throws DataError as insertChild().
    void replaceChild(std::size_t index, Node::Ptr child);

    /// @brief Removes child `index`. Throws DataError on a bad index.
    void removeChild(std::size_t index);

    /// @brief Removes every child.
    void removeAllChildren();

    /// @brief Number of children.
    std::size_t childCount() const { return mChildren.size(); }

    /// @brief Child `index` (< childCount()).
    const Node::Ptr& child(std::size_t index) const { return mChildren[index]; }

    /// @brief All children in order.
    const std::vector<Node::Ptr>& children() const { return mChildren; }

    /// @brief Position of the first occurrence of `node`, if it is a child.
    std::optional<std::size_t> findChild(const Node& node) const;

    /// @brief Traverses every child in order (stops early when the action terminated).
    void doAction(Action& action) override;

protected:
    Group() = default;

    /// @brief Traverses child `index` with `action` (for subclasses that pick children).
    void traverseChild(Action& action, std::size_t index);

private:
    void checkChild(const Node::Ptr& child);
    void checkIndex(std::size_t index, std::size_t limit) const;

    std::vector<Node::Ptr> mChildren;
};

} // namespace texsplat::sg
