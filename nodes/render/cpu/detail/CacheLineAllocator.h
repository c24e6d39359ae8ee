#pragma once

#include "nodes/image/Pixels.h"

#include <cstddef>
#include <new>

namespace texsplat::render::cpu::detail {

/// @brief A std::vector allocator whose memory starts on a 64-byte cache line: rows a whole
/// number of lines long then start on one too, so that SIMD vectors at columns that are a
/// multiple of their width never straddle two lines (a straddling store costs two, and a later
/// load of it cannot take the value straight from the store). As UnsetAllocator, a vector's new
/// elements are left unset (floats not zeroed): their owner clears them, in parallel.
template <typename T> struct CacheLineAllocator : image::UnsetAllocator<T> {
    using value_type = T;
    template <typename U> struct rebind {
        using other = CacheLineAllocator<U>;
    };
    static constexpr std::align_val_t kAlignment{64};

    CacheLineAllocator() = default;
    template <typename U> CacheLineAllocator(const CacheLineAllocator<U>& /*other*/) {}

    T* allocate(std::size_t count) {
        return static_cast<T*>(::operator new(count * sizeof(T), kAlignment));
    }
    void deallocate(T* storage, std::size_t /*count*/) { ::operator delete(storage, kAlignment); }

    template <typename U> bool operator==(const CacheLineAllocator<U>& /*other*/) const {
        return true;
    }
    template <typename U> bool operator!=(const CacheLineAllocator<U>& /*other*/) const {
        return false;
    }
};

} // namespace texsplat::render::cpu::detail
