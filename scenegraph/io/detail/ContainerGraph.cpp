#include "scenegraph/io/detail/ContainerGraph.h"

#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/Group.h"
#include "scenegraph/fields/Field.h"
#include "scenegraph/fields/MFNode.h"
#include "scenegraph/fields/SFNode.h"

#include <vector>

namespace texsplat::sg::detail {

bool isFieldWritten(const Field& field) {
    const Field* source = field.connectedField();
    return (source != nullptr && source->container() != nullptr) ||
           field.connectedOutput() != nullptr || !field.isDefault();
}

void forEachReference(FieldContainer& container,
                      const std::function<void(FieldContainer&)>& visit) {
    for (const Field* field : container.fields()) {
        if (!isFieldWritten(*field)) {
            continue;
        }
        if (const Field* source = field->connectedField(); source != nullptr) {
            if (source->container() != nullptr) {
                visit(*source->container());
            }
        } else if (const EngineOutputBase* output = field->connectedOutput()) {
            visit(output->engine());
        } else if (const auto* single = dynamic_cast<const SFNode*>(field)) {
            if (single->value()) {
                visit(*single->value());
            }
        } else if (const auto* multiple = dynamic_cast<const MFNode*>(field)) {
            for (const std::shared_ptr<Node>& node : multiple->values()) {
                if (node) {
                    visit(*node);
                }
            }
        }
    }
    if (const auto* group = dynamic_cast<const Group*>(container.asNode())) {
        for (const Node::Ptr& child : group->children()) {
            visit(*child);
        }
    }
}

std::unordered_map<const FieldContainer*, std::size_t> countReferences(FieldContainer& root) {
    std::unordered_map<const FieldContainer*, std::size_t> counts{{&root, 1}};
    std::vector<FieldContainer*> pending{&root};
    while (!pending.empty()) {
        FieldContainer* container = pending.back();
        pending.pop_back();
        forEachReference(*container, [&](FieldContainer& referenced) {
            if (++counts[&referenced] == 1) {
                pending.push_back(&referenced);
            }
        });
    }
    return counts;
}

} // namespace texsplat::sg::detail
