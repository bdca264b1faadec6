// Stable sorting for the short arrays of hot paths (the direct calculation's source
// candidates): an insertion sort, since std::stable_sort allocates a buffer on every call.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>

namespace rp {

// As std::stable_sort(first, last, less): elements that compare equal keep their order.
// Up to kSmallSort elements are insertion-sorted in place, more go to std::stable_sort.
constexpr std::ptrdiff_t kSmallSort = 16;
template <class It, class Less>
void stableSortSmall(It first, It last, Less less) {
    if (last - first > kSmallSort) {
        std::stable_sort(first, last, less);
        return;
    }
    for (It i = first; i != last; ++i)
        for (It j = i; j != first && less(*j, *(j - 1)); --j) std::swap(*j, *(j - 1));
}

}  // namespace rp
