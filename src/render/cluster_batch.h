// A batch of work items read on the root and traced by every rank of a cluster (rtrace's
// rays, rcontrib's rays): the root's batch goes to every rank, each traces its slice
// (sliceOf), and the results come back to the root in item order. `put(w, item)` and
// `get(r, item)` write and read what each direction carries.
#pragma once

#include <vector>

#include "util/cluster.h"

namespace rp::render {

// The root's batch, and whether more batches follow, at every rank.
template <class Item, class Put, class Get>
bool shareBatch(Cluster& cluster, std::vector<Item>& batch, bool more, const Put& put,
                const Get& get) {
    ByteWriter w;
    if (cluster.isRoot()) {
        w.put(more);
        w.put(uint64_t(batch.size()));
        for (const Item& item : batch) put(w, item);
    }
    Bytes bytes = std::move(w.bytes());
    cluster.broadcast(bytes);
    if (cluster.isRoot()) return more;
    ByteReader r(bytes);
    more = r.get<bool>();
    batch.resize(size_t(r.get<uint64_t>()));
    for (Item& item : batch) get(r, item);
    return more;
}

// Every rank's results for `mine`, into the root's batch.
template <class Item, class Put, class Get>
void collectSlices(Cluster& cluster, std::vector<Item>& batch, const Slice& mine, const Put& put,
                   const Get& get) {
    ByteWriter w;
    for (size_t k = mine.begin; k < mine.end; ++k) put(w, batch[k]);
    std::vector<size_t> sizes;
    const Bytes all = cluster.gather(w.bytes(), sizes);
    if (!cluster.isRoot()) return;
    ByteReader r(all);
    for (Item& item : batch) get(r, item);
    RP_CHECK(r.done());
}

}  // namespace rp::render
