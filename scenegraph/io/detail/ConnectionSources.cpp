#include "scenegraph/io/detail/ConnectionSources.h"

#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/Group.h"
#include "scenegraph/fields/Field.h"
#include "scenegraph/fields/MFNode.h"
#include "scenegraph/fields/SFNode.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace texsplat::sg::detail {

namespace {

using Edges = std::vector<FieldContainer*>;

// What `container` holds through shared pointers in a graph just read: its children, the nodes in
// its node fields and the engines its fields are connected from (no connection keeps a field's
// container yet).
void addHeld(FieldContainer& container, Edges& held) {
    for (const Field* field : container.fields()) {
        if (const EngineOutputBase* output = field->connectedOutput()) {
            held.push_back(&output->engine());
        } else if (const auto* single = dynamic_cast<const SFNode*>(field)) {
            if (single->value()) {
                held.push_back(single->value().get());
            }
        } else if (const auto* multiple = dynamic_cast<const MFNode*>(field)) {
            for (const std::shared_ptr<Node>& node : multiple->values()) {
                if (node) {
                    held.push_back(node.get());
                }
            }
        }
    }
    if (const auto* group = dynamic_cast<const Group*>(container.asNode())) {
        for (const Node::Ptr& child : group->children()) {
            held.push_back(child.get());
        }
    }
}

// The strongly connected component of every container reachable from `root` through
// `edges(container, out)` (Tarjan's algorithm, without recursion).
template <class EdgesOf>
std::unordered_map<const FieldContainer*, std::size_t> components(FieldContainer& root,
                                                                  const EdgesOf& edgesOf) {
    struct Visit {
        std::size_t index;
        std::size_t lowLink;
        bool isOnStack;
    };
    struct Step {
        FieldContainer* container;
        Edges next;
        std::size_t nextIndex = 0;
    };
    std::unordered_map<const FieldContainer*, Visit> visits;
    std::unordered_map<const FieldContainer*, std::size_t> component;
    std::vector<FieldContainer*> stack;
    std::vector<Step> steps;
    const auto enter = [&](FieldContainer& container) {
        const std::size_t index = visits.size();
        visits.emplace(&container, Visit{index, index, true});
        stack.push_back(&container);
        steps.push_back(Step{&container, {}});
        edgesOf(container, steps.back().next);
    };
    enter(root);
    while (!steps.empty()) {
        Step& step = steps.back();
        Visit& visit = visits.at(step.container);
        if (step.nextIndex < step.next.size()) {
            FieldContainer* next = step.next[step.nextIndex++];
            if (const auto found = visits.find(next); found == visits.end()) {
                enter(*next);
            } else if (found->second.isOnStack) {
                visit.lowLink = std::min(visit.lowLink, found->second.index);
            }
            continue;
        }
        if (visit.lowLink == visit.index) {
            const std::size_t id = component.size();
            FieldContainer* member = nullptr;
            do {
                member = stack.back();
                stack.pop_back();
                visits.at(member).isOnStack = false;
                component.emplace(member, id);
            } while (member != step.container);
        }
        const std::size_t lowLink = visit.lowLink;
        steps.pop_back();
        if (!steps.empty()) {
            Visit& parent = visits.at(steps.back().container);
            parent.lowLink = std::min(parent.lowLink, lowLink);
        }
    }
    return component;
}

} // namespace

const ReadConnection* keepUnheldSources(Node& root,
                                        const std::vector<ReadConnection>& connections) {
    // The connections still in place, by the container of the connected field.
    std::unordered_multimap<const FieldContainer*, const ReadConnection*> byField;
    for (const ReadConnection& connection : connections) {
        const Field* from = connection.field->connectedField();
        if (from != nullptr && from->container() == connection.source.get()) {
            byField.emplace(connection.field->container(), &connection);
        }
    }
    // What the root holds, growing as connections keep their sources; and the connections of
    // fields whose containers are held.
    std::unordered_set<const FieldContainer*> held;
    std::vector<const ReadConnection*> pending;
    const auto hold = [&](FieldContainer& start) {
        Edges todo;
        if (held.insert(&start).second) {
            todo.push_back(&start);
        }
        while (!todo.empty()) {
            FieldContainer* container = todo.back();
            todo.pop_back();
            const auto [first, last] = byField.equal_range(container);
            for (auto entry = first; entry != last; ++entry) {
                pending.push_back(entry->second);
            }
            Edges next;
            addHeld(*container, next);
            for (FieldContainer* reached : next) {
                if (held.insert(reached).second) {
                    todo.push_back(reached);
                }
            }
        }
    };
    hold(root);
    // A connection may keep its source only where that cannot close a cycle of holders: where
    // the source and the connected field's container are in different components of the graph
    // in which every connection that might keep its source (one the root does not hold) does.
    const auto component = components(root, [&](FieldContainer& container, Edges& next) {
        addHeld(container, next);
        const auto [first, last] = byField.equal_range(&container);
        for (auto entry = first; entry != last; ++entry) {
            if (held.count(entry->second->source.get()) == 0) {
                next.push_back(entry->second->source.get());
            }
        }
    });
    std::unordered_set<const ReadConnection*> cyclic;
    while (!pending.empty()) {
        const ReadConnection* connection = pending.back();
        pending.pop_back();
        FieldContainer& source = *connection->source;
        if (held.count(&source) != 0) {
            continue;
        }
        if (component.at(connection->field->container()) == component.at(&source)) {
            cyclic.insert(connection);
            continue;
        }
        connection->field->keepSourceAlive();
        hold(source);
    }
    for (const ReadConnection& connection : connections) {
        if (cyclic.count(&connection) != 0 && held.count(connection.source.get()) == 0) {
            return &connection;
        }
    }
    return nullptr;
}

} // namespace texsplat::sg::detail
