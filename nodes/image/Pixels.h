#pragma once

#include <glm/vec4.hpp>

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace texsplat::image {

/// @brief std::allocator, except that a vector's new elements are default-initialised instead of
/// value-initialised: a glm::vec4 (whose default constructor is defaulted) is left unset, not
/// zeroed, when the vector is resized without a value. For images whose producer writes every
/// pixel, which would otherwise pay for a clear of 16 bytes a pixel on one thread (and its page
/// faults) before overwriting them all. Elements given a value (assign(n, value)) get it.
template <typename T> struct UnsetAllocator : std::allocator<T> {
    template <typename U> struct rebind {
        using other = UnsetAllocator<U>;
    };

    UnsetAllocator() = default;
    template <typename U> UnsetAllocator(const UnsetAllocator<U>& other) noexcept
        : std::allocator<T>(other) {}

    template <typename U> void construct(U* element) { ::new (static_cast<void*>(element)) U; }
    template <typename U, typename... Arguments>
    void construct(U* element, Arguments&&... arguments) {
        ::new (static_cast<void*>(element)) U(std::forward<Arguments>(arguments)...);
    }
};

/// @brief An image's premultiplied RGBA pixels, top row first (Image).
using Pixels = std::vector<glm::vec4, UnsetAllocator<glm::vec4>>;

} // namespace texsplat::image
