// A batch of work items read on the root and traced by every rank of a cluster (rtrace's
// rays, rcontrib's rays): the root's batch goes to every rank, each traces its slice
// (sliceOf), and the results come back to the root in item order. A Codec says what each
// direction carries: static putRay/getRay (root to ranks) and putResult/getResult (back).
#pragma once

#include <vector>

#include "util/cluster.h"

namespace rp::render {

// This process's part in a batch loop; a null cluster (or one of one rank) is the whole.
class BatchRole {
public:
    explicit BatchRole(Cluster* cluster) : cluster_(distributed(cluster) ? cluster : nullptr) {}

    bool root() const { return !cluster_ || cluster_->isRoot(); }
    int ranks() const { return cluster_ ? cluster_->size() : 1; }
    // This rank's items of a batch of n.
    Slice slice(size_t n) const {
        return cluster_ ? sliceOf(n, cluster_->rank(), cluster_->size()) : Slice{0, n};
    }

    // The root's batch, and whether more batches follow, at every rank.
    template <class Codec, class Item>
    bool share(std::vector<Item>& batch, bool more) const {
        if (!cluster_) return more;
        ByteWriter w;
        if (root()) {
            w.put(more);
            w.put(uint64_t(batch.size()));
            for (const Item& item : batch) Codec::putRay(w, item);
        }
        Bytes bytes = std::move(w.bytes());
        cluster_->broadcast(bytes);
        if (root()) return more;
        ByteReader r(bytes);
        more = r.get<bool>();
        batch.resize(size_t(r.get<uint64_t>()));
        for (Item& item : batch) Codec::getRay(r, item);
        return more;
    }

    // Every rank's results for its slice `mine`, into the root's batch.
    template <class Codec, class Item>
    void collect(std::vector<Item>& batch, const Slice& mine) const {
        if (!cluster_) return;
        ByteWriter w;
        for (size_t k = mine.begin; k < mine.end; ++k) Codec::putResult(w, batch[k]);
        std::vector<size_t> sizes;
        const Bytes all = cluster_->gather(w.bytes(), sizes);
        if (!root()) return;
        ByteReader r(all);
        for (Item& item : batch) Codec::getResult(r, item);
        RP_CHECK(r.done());
    }

private:
    Cluster* cluster_;
};

}  // namespace rp::render
