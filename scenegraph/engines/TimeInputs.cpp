#include "scenegraph/engines/TimeInputs.h"

#include "scenegraph/Engine.h"
#include "scenegraph/Node.h"
#include "scenegraph/io/detail/ContainerGraph.h"

#include <unordered_set>
#include <vector>

namespace texsplat::sg {

std::size_t connectTimeInputs(Node& root, SFFloat& time) {
    // Depth-first in graph order, not in address order: the order of the connections is the
    // order in which engines hear each new time, and so the order in which the sensors they
    // trigger run. It must be the same in every run.
    std::size_t count = 0;
    std::unordered_set<const FieldContainer*> seen{&root};
    std::vector<FieldContainer*> pending{&root};
    while (!pending.empty()) {
        FieldContainer& container = *pending.back();
        pending.pop_back();
        Field* input = container.asNode() == nullptr ? container.findField("timeIn") : nullptr;
        if (input != nullptr && input->typeName() == time.typeName() && !input->isConnected()) {
            input->connectFrom(time);
            ++count;
        }
        detail::forEachReference(container, [&](FieldContainer& referenced) {
            if (seen.insert(&referenced).second) {
                pending.push_back(&referenced);
            }
        });
    }
    return count;
}

} // namespace texsplat::sg
