#pragma once

#include "scenegraph/Fwd.h"

#include <unordered_map>

namespace texsplat::sg {

namespace detail {
template <class MemberFunction> struct MemberMethod;
template <class N, class A> struct MemberMethod<void (N::*)(A&)> {
    using NodeClass = N;
    using ActionClass = A;
};
} // namespace detail

/// @brief What one action class does for each node type, with inheritance fallback (as Coin's
/// per-action method lists).
///
/// Each action class owns one table (`static MethodTable& methods()`), filled when first used
/// with the entries it needs; `Action::traverse()` looks up the node's type, then its parent
/// types, and falls back to `Node::doAction()`. So an action added later, in another library,
/// gives node types behaviour without touching Node:
/// @code
/// // with void ScalarSplat::collectFrame(FrameAction&):
/// FrameAction::methods().add<&ScalarSplat::collectFrame>();
/// @endcode
/// Tables are written at start-up (before traversals run on other threads) and only read
/// during traversal.
class MethodTable {
public:
    /// @brief One entry: does the action's work for one node.
    using Method = void (*)(Action& action, Node& node);

    /// @brief Sets (or replaces) the method for `type` and the types derived from it that have
    /// no entry of their own.
    void add(const NodeType& type, Method method) { mMethods[&type] = method; }

    /// @brief Registers a member function `void N::fn(A&)` for `N::classType()`, where `A` is
    /// the action class; virtual functions dispatch to the node's override.
    template <auto MemberFunction> void add() {
        using Traits = detail::MemberMethod<decltype(MemberFunction)>;
        using N = typename Traits::NodeClass;
        using A = typename Traits::ActionClass;
        add(N::classType(), [](Action& action, Node& node) {
            (static_cast<N&>(node).*MemberFunction)(static_cast<A&>(action));
        });
    }

    /// @brief The method for `type` or its nearest ancestor type, or nullptr.
    Method find(const NodeType& type) const;

private:
    std::unordered_map<const NodeType*, Method> mMethods;
};

} // namespace texsplat::sg
