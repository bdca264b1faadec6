// This process alone as a cluster of one (cluster.h).
#include "util/cluster.h"

#include <algorithm>

namespace rp {

Bytes Cluster::gather(std::span<const std::byte> mine, std::vector<size_t>& sizes) {
    sizes.clear();
    if (!isRoot()) {
        send(0, mine);
        return {};
    }
    Bytes all(mine.begin(), mine.end());
    sizes.push_back(mine.size());
    for (int r = 1; r < size(); ++r) {
        Bytes part = receive(r);
        sizes.push_back(part.size());
        all.insert(all.end(), part.begin(), part.end());
    }
    return all;
}

Bytes Cluster::allGather(std::span<const std::byte> mine, std::vector<size_t>& sizes) {
    Bytes all = gather(mine, sizes);
    ByteWriter w;
    w.putVector(sizes);
    Bytes head = std::move(w.bytes());
    broadcast(head);
    ByteReader(head).getVector(sizes);
    broadcast(all);
    return all;
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
