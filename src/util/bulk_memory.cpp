// Huge-page advice (see bulk_memory.h).
#include "util/bulk_memory.h"

#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rp {

void adviseHugePages(void* p, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr uintptr_t kHuge = uintptr_t{2} << 20;
    const uintptr_t begin = (reinterpret_cast<uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
    const uintptr_t end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(kHuge - 1);
    // Advice only: if the kernel refuses (no THP), the memory simply stays in small pages.
    if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

namespace {
constexpr size_t kHugePage = size_t{2} << 20;
size_t roundToHugePages(size_t bytes) { return (bytes + kHugePage - 1) & ~(kHugePage - 1); }
}  // namespace

void* allocateHugePages(size_t bytes) {
    const size_t size = roundToHugePages(bytes);
#if defined(__linux__)
    // Map one huge page more than needed and unmap the unaligned ends.
    void* m = ::mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                     -1, 0);
    if (m == MAP_FAILED) throw std::bad_alloc();
    const uintptr_t raw = reinterpret_cast<uintptr_t>(m);
    const uintptr_t begin = (raw + kHugePage - 1) & ~(kHugePage - 1);
    if (begin > raw) ::munmap(m, begin - raw);
    const uintptr_t tail = raw + size + kHugePage - (begin + size);
    if (tail > 0) ::munmap(reinterpret_cast<void*>(begin + size), tail);
    void* p = reinterpret_cast<void*>(begin);
#else
    void* p = ::operator new (size, std::align_val_t{kHugePage});
#endif
    adviseHugePages(p, size);
    return p;
}

void freeHugePages(void* p, size_t bytes) {
#if defined(__linux__)
    ::munmap(p, roundToHugePages(bytes));
#else
    (void)bytes;
    ::operator delete (p, std::align_val_t{kHugePage});
#endif
}

}  // namespace rp
