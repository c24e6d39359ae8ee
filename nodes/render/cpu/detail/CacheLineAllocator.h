#pragma once

#include <cstddef>
#include <new>

namespace texsplat::render::cpu::detail {

/// @brief A std::vector allocator whose memory starts on a 64-byte cache line: rows a whole
/// number of lines long then start on one too, so that SIMD vectors at columns that are a
/// multiple of their width never straddle two lines (a straddling store costs two, and a later
/// load of it cannot take the value straight from the store).
template <typename T> struct CacheLineAllocator {
    using value_type = T;
    static constexpr std::align_val_t kAlignment{64};

    CacheLineAllocator() = default;
    template <typename U> CacheLineAllocator(const CacheLineAllocator<U>& /*other*/) {}

    T* allocate(std::size_t count) {
        return static_cast<T*>(::operator new(count * sizeof(T), kAlignment));
    }
    void deallocate(T* pointer, std::size_t /*count*/) { ::operator delete(pointer, kAlignment); }

    template <typename U> bool operator==(const CacheLineAllocator<U>& /*other*/) const {
        return true;
    }
    template <typename U> bool operator!=(const CacheLineAllocator<U>& /*other*/) const {
        return false;
    }
};

} // namespace texsplat::render::cpu::detail
