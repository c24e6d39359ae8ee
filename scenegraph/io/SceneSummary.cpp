#include "scenegraph/io/SceneSummary.h"

#include "scenegraph/Node.h"
#include "scenegraph/io/detail/ContainerGraph.h"

namespace texsplat::sg {

namespace {

std::string counted(std::size_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

} // namespace

SceneSummary::SceneSummary(FieldContainer& root) {
    for (const auto& [container, references] : detail::countReferences(root)) {
        ++(dynamic_cast<const Node*>(container) != nullptr ? mNodeCount : mEngineCount);
        mSharedCount += references > 1 ? 1 : 0;
        ++mTypeCounts[container->typeName()];
    }
}

std::string SceneSummary::text() const {
    std::string text = counted(mNodeCount, "node") + ", " + counted(mEngineCount, "engine") +
                       ", " + std::to_string(mSharedCount) + " shared;";
    const char* separator = " ";
    for (const auto& [type, count] : mTypeCounts) {
        text += separator + type + " " + std::to_string(count);
        separator = ", ";
    }
    return text;
}

} // namespace texsplat::sg
