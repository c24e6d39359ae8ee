#pragma once

#include "scenegraph/actions/Action.h"

#include <optional>
#include <string>
#include <vector>

namespace texsplat::sg {

/// @brief Finds nodes by name and/or type and returns the paths to them.
///
/// Set the criteria (a node matches all that are set), then `apply(root)`. With
/// Interest::First the traversal stops at the first match (in traversal order); with All every
/// match is returned, a shared node once per path that reaches it. Switches are searched as
/// they would be traversed unless `setSearchingAll(true)`.
class SearchAction : public Action {
public:
    /// @brief How many matches to collect.
    enum class Interest { First, All };

    SearchAction();

    /// @brief The table of this action: `Node` → `Node::search()`.
    static MethodTable& methods();

    /// @brief Match nodes named `name`.
    void setName(std::string name) { mName = std::move(name); }

    /// @brief Match nodes of `type` (and of derived types when `derived`).
    void setType(const NodeType& type, bool derived = true);

    /// @brief First (default) or All.
    void setInterest(Interest interest) { mInterest = interest; }

    /// @brief Also search the children a Switch would skip.
    void setSearchingAll(bool searchingAll) { mIsSearchingAll = searchingAll; }

    /// @brief Whether Switch children are all searched.
    bool isSearchingAll() const { return mIsSearchingAll; }

    /// @brief True when `node` meets every criterion set.
    bool matches(const Node& node) const;

    /// @brief Records the current path if the current node matches; terminates for First.
    void checkCurrent(const Node& node);

    /// @brief Paths to the matches of the last apply().
    const std::vector<Path>& paths() const { return mPaths; }

protected:
    /// @brief Clears the matches.
    void beginTraversal(Node& root) override;

private:
    std::optional<std::string> mName;
    const NodeType* mType = nullptr;
    bool mIsDerivedTypeMatching = true;
    Interest mInterest = Interest::First;
    bool mIsSearchingAll = false;
    std::vector<Path> mPaths;
};

} // namespace texsplat::sg
