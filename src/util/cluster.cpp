// This process alone as a cluster of one (cluster.h).
#include "util/cluster.h"

#include <algorithm>

namespace rp {

Bytes LocalCluster::gather(std::span<const std::byte> mine, std::vector<size_t>& sizes) {
    sizes.assign(1, mine.size());
    return Bytes(mine.begin(), mine.end());
}

Bytes LocalCluster::allGather(std::span<const std::byte> mine, std::vector<size_t>& sizes) {
    return gather(mine, sizes);
}

void LocalCluster::send(int, std::span<const std::byte>) {
    RP_CHECK(!"a cluster of one has no other rank to send to");
}

Bytes LocalCluster::receive(int) {
    RP_CHECK(!"a cluster of one has no other rank to receive from");
    return {};
}

Slice sliceOf(size_t n, int rank, int size) {
    RP_CHECK(size > 0 && rank >= 0 && rank < size);
    const size_t q = n / size_t(size), r = n % size_t(size), k = size_t(rank);
    Slice s;
    s.begin = k * q + std::min(k, r);
    s.end = s.begin + q + (k < r ? 1 : 0);
    return s;
}

}  // namespace rp
