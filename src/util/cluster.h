// The processes one run is spread over: MPI ranks in an MPI build (src/mpi), or this
// process alone. mkpmap, rtrace, rcontrib and rpict take a Cluster* (null: this process
// alone) and split their work so that the result is the same for any number of ranks:
// the root (rank 0) reads the input and writes every output; the others trace.
// Messages are plain bytes, written and read with ByteWriter/ByteReader.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "util/error.h"

namespace rp {

using Bytes = std::vector<std::byte>;

class Cluster {
public:
    virtual ~Cluster() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    bool isRoot() const { return rank() == 0; }

    // The root's `bytes`, given to every rank (resized there).
    virtual void broadcast(Bytes& bytes) = 0;
    // Point to point; messages from one rank to another arrive in the order sent.
    virtual void send(int to, std::span<const std::byte> bytes) = 0;
    virtual Bytes receive(int from) = 0;
    // Ends every rank of the run now (a rank that cannot go on must not leave the others
    // waiting for it). Returns only for a cluster of one.
    virtual void abortAll(int exitCode) = 0;

    // Every rank's `mine`, at the root in rank order (`sizes` gets each length); other
    // ranks get nothing back. Point to point rather than MPI_Gatherv, whose int
    // displacements cap the total.
    Bytes gather(std::span<const std::byte> mine, std::vector<size_t>& sizes);
    // Every rank's `mine` in rank order, at every rank.
    Bytes allGather(std::span<const std::byte> mine, std::vector<size_t>& sizes);
};

// This process alone: rank 0 of 1.
class LocalCluster final : public Cluster {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    void broadcast(Bytes&) override {}
    void send(int, std::span<const std::byte>) override;
    Bytes receive(int) override;
    void abortAll(int) override {}
};

// More than one rank (a null cluster is this process alone).
inline bool distributed(const Cluster* c) { return c && c->size() > 1; }

// [begin, end) of n items that rank `rank` of `size` takes: contiguous, in rank order,
// sizes differing by at most one.
struct Slice {
    size_t begin = 0, end = 0;
};
Slice sliceOf(size_t n, int rank, int size);

// Appends trivially copyable values to a message.
class ByteWriter {
public:
    template <class T>
    void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        append(&v, sizeof v);
    }
    template <class T>
    void putVector(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        put(uint64_t(v.size()));
        append(v.data(), v.size() * sizeof(T));
    }
    void putString(const std::string& s) {
        put(uint64_t(s.size()));
        append(s.data(), s.size());
    }
    Bytes& bytes() { return bytes_; }

private:
    void append(const void* p, size_t n) {
        const size_t at = bytes_.size();
        bytes_.resize(at + n);
        if (n) std::memcpy(bytes_.data() + at, p, n);
    }
    Bytes bytes_;
};

// Reads what ByteWriter wrote, in the same order. Messages come from our own ranks, so
// a short one is a programming error (RP_CHECK), not bad input.
class ByteReader {
public:
    explicit ByteReader(std::span<const std::byte> bytes) : bytes_(bytes) {}
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        take(&v, sizeof v);
        return v;
    }
    template <class T>
    void getVector(std::vector<T>& v) {
        const uint64_t n = get<uint64_t>();
        RP_CHECK(n <= (bytes_.size() - at_) / sizeof(T));
        v.resize(size_t(n));
        take(v.data(), size_t(n) * sizeof(T));
    }
    std::string getString() {
        const uint64_t n = get<uint64_t>();
        RP_CHECK(n <= bytes_.size() - at_);
        std::string s(size_t(n), '\0');
        take(s.data(), size_t(n));
        return s;
    }
    bool done() const { return at_ == bytes_.size(); }

private:
    void take(void* p, size_t n) {
        RP_CHECK(n <= bytes_.size() - at_);
        if (n) std::memcpy(p, bytes_.data() + at_, n);
        at_ += n;
    }
    std::span<const std::byte> bytes_;
    size_t at_ = 0;
};

// The root's `value`, at every rank.
template <class T>
T broadcastValue(Cluster* cluster, const T& value) {
    if (!distributed(cluster)) return value;
    ByteWriter w;
    w.put(value);
    Bytes bytes = std::move(w.bytes());
    cluster->broadcast(bytes);
    return ByteReader(bytes).get<T>();
}

}  // namespace rp
