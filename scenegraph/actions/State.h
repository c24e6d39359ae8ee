#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace texsplat::sg {

namespace detail {
/// Dense id per element type, assigned on first use.
std::size_t nextStateElementId();
template <class E> std::size_t stateElementId() {
    static const std::size_t id = nextStateElementId();
    return id;
}
} // namespace detail

/// @brief The traversal state of an action: one current value per element type, saved and
/// restored by `push()`/`pop()` (Separator).
///
/// An element is any copyable, default-constructible type; its default-constructed value is
/// the state at the start of a traversal. Actions in other libraries add their own elements
/// (camera, material, transfer function) without registering them anywhere:
/// @code
/// struct ModelMatrixElement { glm::mat4 matrix{1.0f}; };
/// state.modify<ModelMatrixElement>().matrix *= local;   // saved for the enclosing pop()
/// const glm::mat4& m = state.get<ModelMatrixElement>().matrix;
/// @endcode
/// Saving is lazy: `push()` copies nothing; the first `modify()` of an element after a push
/// saves its previous value, which `pop()` restores.
class State {
public:
    State() = default;
    State(const State&) = delete;
    State& operator=(const State&) = delete;

    /// @brief The current value of element `E` (default-constructed if never modified).
    template <class E> const E& get() { return slot<E>().value; }

    /// @brief The current value of element `E`, writable; saves the old value for pop().
    template <class E> E& modify() {
        const std::size_t id = detail::stateElementId<E>();
        Slot<E>& current = slot<E>();
        if (mFrames.size() > 1 && mSavedDepth[id] != mFrames.size()) {
            mFrames.back().push_back({id, mSavedDepth[id], std::make_unique<Slot<E>>(current)});
            mSavedDepth[id] = mFrames.size();
        }
        return current.value;
    }

    /// @brief Starts a scope whose modifications pop() undoes.
    void push();

    /// @brief Restores every element modified since the matching push().
    void pop();

    /// @brief Number of open push() scopes.
    std::size_t depth() const { return mFrames.size() - 1; }

    /// @brief Back to the initial state (all elements default, no scopes).
    void reset();

private:
    struct SlotBase {
        virtual ~SlotBase() = default;
    };
    template <class E> struct Slot final : SlotBase {
        E value{};
    };
    struct Saved {
        std::size_t id;
        std::size_t savedDepth;
        std::unique_ptr<SlotBase> slot;
    };

    template <class E> Slot<E>& slot() {
        const std::size_t id = detail::stateElementId<E>();
        if (id >= mSlots.size()) {
            mSlots.resize(id + 1);
            mSavedDepth.resize(id + 1, 0);
        }
        if (!mSlots[id]) {
            mSlots[id] = std::make_unique<Slot<E>>();
        }
        return static_cast<Slot<E>&>(*mSlots[id]);
    }

    std::vector<std::unique_ptr<SlotBase>> mSlots;
    // Frame depth at which each slot was last saved, so one scope saves an element only once.
    std::vector<std::size_t> mSavedDepth;
    // Frame 0 is the base scope (never popped); each push() adds one.
    std::vector<std::vector<Saved>> mFrames = std::vector<std::vector<Saved>>(1);
};

} // namespace texsplat::sg
