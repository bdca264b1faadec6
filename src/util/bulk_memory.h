// Large arrays written once in parallel: huge-page advice and an allocator that neither
// zero-fills nor leaves big blocks on 4 KiB pages (photon maps, their indices, mkpmap).
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace rp {

// Advises the kernel to back [p, p + bytes) with transparent huge pages (Linux
// MADV_HUGEPAGE; the 2 MiB-aligned part only; a no-op elsewhere). Why: on the virtual
// machines we measure on, first touching fresh memory costs ~3 ms per MiB in 4 KiB page
// faults, more than decoding a photon map or building its index; with huge pages it is
// ~0.1 ms per MiB. Call before the memory is first written.
void adviseHugePages(void* p, size_t bytes);

// `bytes` rounded up to whole 2 MiB pages, 2 MiB-aligned, advised for huge pages before
// anything touches them; throws std::bad_alloc. Mapped directly (Linux mmap), not taken
// from malloc's heap: heap blocks advised this way were still faulted in 4 KiB pages at
// times (seen: 505 faults for a 2 MB index array). freeHugePages takes the same `bytes`.
void* allocateHugePages(size_t bytes);
void freeHugePages(void* p, size_t bytes);

// An allocator for the large arrays of photon maps and their indices: resize() leaves
// elements uninitialised (each is written once by a parallel loop, so a zero fill would only
// add a serial pass over the memory), and blocks of 1 MiB or more come from
// allocateHugePages. Rounding up to whole huge pages: a 4 MB array otherwise had its last
// 1.9 MB in 4 KiB pages (466 page faults, against 2 for the whole array), and a 2.0 MB
// one, just under 2 MiB, all of it.
template <class T>
struct BulkAllocator {
    using value_type = T;
    BulkAllocator() = default;
    template <class U>
    BulkAllocator(const BulkAllocator<U>&) {}
    static constexpr size_t kHugeThreshold = size_t{1} << 20;
    T* allocate(size_t n) {
        const size_t bytes = n * sizeof(T);
        if (bytes < kHugeThreshold) return std::allocator<T>().allocate(n);
        return static_cast<T*>(allocateHugePages(bytes));
    }
    void deallocate(T* p, size_t n) {
        if (n * sizeof(T) < kHugeThreshold)
            std::allocator<T>().deallocate(p, n);
        else
            freeHugePages(p, n * sizeof(T));
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        if constexpr (sizeof...(Args) == 0)
            ::new (static_cast<void*>(p)) U;
        else
            ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U>
    bool operator==(const BulkAllocator<U>&) const {
        return true;
    }
};
template <class T>
using BulkVector = std::vector<T, BulkAllocator<T>>;

}  // namespace rp
