// The in-core store written out and read back (incore_store.h writeIndex/readIndex), so
// that a map opened again skips the build: reading the arrays back costs a copy, where
// the build sorts and lays out every photon (bench/README_speed.md, map loading).
//
// Layout: a fixed head (magic, its own size as a 4-byte word at byte 8, format version,
// byte-order mark, the caller's key, photon count, attributes, leaf size, bounds, array
// lengths, and in its last four bytes the CRC-32 of the body), then the body: nodes, leaf
// blocks, flux, and the flags, primaries and normals the attributes ask for, each as in
// memory. A cache for this machine, not an exchange format: the byte-order mark and the
// sizes of the records refuse a file from another layout.
#include <algorithm>
#include <cstddef>
#include <istream>
#include <ostream>
#include <vector>

#include "pmap/incore_store.h"
#include "pmap/record_checksums.h"

namespace rp::pmap {

namespace {

constexpr char kMagic[8] = {'R', 'P', 'S', 'T', 'O', 'R', 'E', '\n'};
constexpr uint32_t kIndexVersion = 2;
constexpr uint32_t kByteOrder = 0x01020304;
constexpr uint32_t kLeafTag = 3;

struct Head {
    char magic[8];
    uint32_t headBytes;  // sizeof(Head): where the body starts
    uint32_t version;
    uint32_t byteOrder;
    uint32_t reserved;  // 0; no implicit padding: every byte of the head is written
    uint64_t key[3];
    uint64_t photons;
    uint32_t attributes;  // bit 0: normals, bit 1: contrib
    uint32_t leafSize;
    float lo[3], hi[3];
    uint64_t nodes;
    uint64_t slots;
    uint32_t nodeBytes;  // sizeof(Node): a layout check
    uint32_t bodyCrc;    // the head's last four bytes
};
static_assert(sizeof(Head) == 112 && offsetof(Head, bodyCrc) + 4 == sizeof(Head));

uint32_t attributeBits(InCoreStore::Attributes a) {
    return (a.normals ? 1u : 0u) | (a.contrib ? 2u : 0u);
}

}  // namespace

struct InCoreStore::Index {
    // The arrays of `s` in file order, as (pointer, bytes).
    template <class S, class F>
    static void eachArray(S& s, F f) {
        f(s.nodes_.data(), s.nodes_.size() * sizeof(Node));
        f(s.leaves_.data(), s.leaves_.size());
        f(s.flux_.data(), s.flux_.size() * sizeof(Colr));
        f(s.flags_.data(), s.flags_.size());
        f(s.primary_.data(), s.primary_.size() * sizeof(uint32_t));
        f(s.norm_.data(), s.norm_.size() * 3);
    }

    // Whether the nodes make a tree the search walks safely: children after their parent
    // (no cycle), every node reached once, depth within the search's stack, leaves' slots
    // inside the arrays, and the leaves holding `photons` in all.
    static bool wellFormed(const InCoreStore& s, uint64_t photons) {
        const std::vector<Node>& nodes = s.nodes_;
        const uint64_t slots = s.flux_.size();
        struct Item {
            uint32_t id;
            int depth;
        };
        std::vector<Item> stack{{0, 0}};
        std::vector<bool> seen(nodes.size());
        uint64_t held = 0;
        while (!stack.empty()) {
            const Item it = stack.back();
            stack.pop_back();
            if (it.depth > 96 || seen[it.id]) return false;  // build: depth <= 96
            seen[it.id] = true;
            const Node& n = nodes[it.id];
            if ((n.axisInfo & 3) == kLeafTag) {
                const uint32_t count = n.axisInfo >> 2;
                if (count == 0 || count > kLeafSize || n.link % 4 != 0 ||
                    uint64_t{n.link} + paddedCount(count) > slots)
                    return false;
                held += count;
                continue;
            }
            if (n.axisInfo > 2 || !(n.leftMax <= n.rightMin) || it.id + 1 >= nodes.size() ||
                n.link <= it.id + 1 || n.link >= nodes.size())
                return false;
            stack.push_back({n.link, it.depth + 1});
            stack.push_back({it.id + 1, it.depth + 1});
        }
        return std::find(seen.begin(), seen.end(), false) == seen.end() && held == photons;
    }
};

void InCoreStore::writeIndex(std::ostream& out, const IndexKey& key) const {
    Head h{};
    std::copy(std::begin(kMagic), std::end(kMagic), h.magic);
    h.headBytes = sizeof(Head);
    h.version = kIndexVersion;
    h.byteOrder = kByteOrder;
    for (int i = 0; i < 3; ++i) h.key[i] = key[size_t(i)];
    h.photons = size_;
    h.attributes = attributeBits(attrs_);
    h.leafSize = kLeafSize;
    for (int a = 0; a < 3; ++a) {
        h.lo[a] = boundsLo_[a];
        h.hi[a] = boundsHi_[a];
    }
    h.nodes = nodes_.size();
    h.slots = flux_.size();
    h.nodeBytes = sizeof(Node);
    uint32_t crc = 0u;
    Index::eachArray(*this, [&](const void* p, size_t bytes) {
        crc = extendChecksum(crc, static_cast<const unsigned char*>(p), bytes);
    });
    h.bodyCrc = crc;
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    Index::eachArray(*this, [&](const void* p, size_t bytes) {
        out.write(static_cast<const char*>(p), std::streamsize(bytes));
    });
}

std::optional<InCoreStore> InCoreStore::readIndex(std::istream& in, const IndexKey& key,
                                                  Attributes attrs, uint64_t photons) {
    Head h{};
    if (!in.read(reinterpret_cast<char*>(&h), sizeof h)) return std::nullopt;
    const bool headOk = std::equal(std::begin(kMagic), std::end(kMagic), h.magic) &&
                        h.headBytes == sizeof(Head) && h.version == kIndexVersion &&
                        h.byteOrder == kByteOrder && h.key[0] == key[0] && h.key[1] == key[1] &&
                        h.key[2] == key[2] && h.photons == photons && photons > 0 &&
                        h.attributes == attributeBits(attrs) && h.leafSize == kLeafSize &&
                        h.nodeBytes == sizeof(Node) && h.nodes > 0 && h.nodes <= 2 * photons + 1 &&
                        h.slots >= photons && h.slots <= photons + 4 * h.nodes;
    if (!headOk) return std::nullopt;
    InCoreStore s;
    s.size_ = photons;
    s.attrs_ = attrs;
    for (int a = 0; a < 3; ++a) {
        s.boundsLo_[a] = h.lo[a];
        s.boundsHi_[a] = h.hi[a];
    }
    s.nodes_.resize(h.nodes);
    s.leaves_.resize(kLeafBytesPerSlot * h.slots);
    s.flux_.resize(h.slots);
    if (attrs.contrib) {
        s.flags_.resize(h.slots);
        s.primary_.resize(h.slots);
    }
    if (attrs.normals) s.norm_.resize(h.slots);
    bool ok = true;
    uint32_t crc = 0u;
    Index::eachArray(s, [&](void* p, size_t bytes) {
        ok = ok && in.read(static_cast<char*>(p), std::streamsize(bytes));
        if (ok) crc = extendChecksum(crc, static_cast<const unsigned char*>(p), bytes);
    });
    // Nothing may follow: a longer file is not the one this head describes.
    if (!ok || crc != h.bodyCrc || in.peek() != std::char_traits<char>::eof()) return std::nullopt;
    if (!Index::wellFormed(s, photons)) return std::nullopt;
    return s;
}

}  // namespace rp::pmap
