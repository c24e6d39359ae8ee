#include "scenegraph/actions/detail/VisitCount.h"

#include "scenegraph/Group.h"

#include <limits>
#include <unordered_map>
#include <vector>

namespace texsplat::sg::detail {

namespace {

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
    return a > std::numeric_limits<std::uint64_t>::max() - b
               ? std::numeric_limits<std::uint64_t>::max()
               : a + b;
}

const std::vector<Node::Ptr>* childrenOf(const Node& node) {
    const auto* group = dynamic_cast<const Group*>(&node);
    return group != nullptr ? &group->children() : nullptr;
}

} // namespace

VisitCount countVisits(const Node& root, std::uint64_t limit) {
    struct Frame {
        const Node* node;
        const std::vector<Node::Ptr>* children;
        std::size_t next;
        std::uint64_t visits;
    };
    // Only shared nodes are remembered: a node with one parent is reached once per visit of
    // that parent, whose own count is computed once.
    std::unordered_map<const Node*, std::uint64_t> sharedCounts;
    std::vector<Frame> pending{{&root, childrenOf(root), 0, 1}};
    std::uint64_t total = 0;
    while (!pending.empty()) {
        Frame& top = pending.back();
        if (top.children != nullptr && top.next < top.children->size()) {
            const Node& child = *(*top.children)[top.next++];
            if (const auto known = sharedCounts.find(&child); known != sharedCounts.end()) {
                top.visits = saturatingAdd(top.visits, known->second);
            } else {
                pending.push_back({&child, childrenOf(child), 0, 1});
            }
            continue;
        }
        const Frame done = top;
        pending.pop_back();
        if (done.visits > limit) {
            return {done.visits, done.node};
        }
        if (done.node->parents().size() > 1) {
            sharedCounts.emplace(done.node, done.visits);
        }
        if (pending.empty()) {
            total = done.visits;
        } else {
            pending.back().visits = saturatingAdd(pending.back().visits, done.visits);
        }
    }
    return {total, nullptr};
}

} // namespace texsplat::sg::detail
