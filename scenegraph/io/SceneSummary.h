#pragma once

#include "scenegraph/Fwd.h"

#include <cstddef>
#include <map>
#include <string>

namespace texsplat::sg {

/// @brief What a graph holds: its distinct nodes and engines by type, and how many are
/// shared (referenced more than once). Counted over everything a file of the graph would
/// contain: children, node-valued fields, connection sources.
class SceneSummary {
public:
    /// @brief Counts the graph under `root`.
    explicit SceneSummary(FieldContainer& root);

    /// @brief Distinct nodes.
    std::size_t nodeCount() const { return mNodeCount; }

    /// @brief Distinct engines.
    std::size_t engineCount() const { return mEngineCount; }

    /// @brief Nodes and engines referenced more than once (written with DEF/USE).
    std::size_t sharedCount() const { return mSharedCount; }

    /// @brief Distinct nodes and engines per type name.
    const std::map<std::string, std::size_t>& typeCounts() const { return mTypeCounts; }

    /// @brief One line: "5 nodes, 1 engine, 2 shared; Group 2, Separator 1, ...".
    std::string text() const;

private:
    std::size_t mNodeCount = 0;
    std::size_t mEngineCount = 0;
    std::size_t mSharedCount = 0;
    std::map<std::string, std::size_t> mTypeCounts;
};

} // namespace texsplat::sg
