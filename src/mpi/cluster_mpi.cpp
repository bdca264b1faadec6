// MPI_COMM_WORLD as a Cluster (cluster_mpi.h).
#include "mpi/cluster_mpi.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <memory>
#include <vector>

namespace rp {

namespace {

// MPI counts are ints: larger messages go in pieces of at most 1 GiB.
constexpr size_t kPiece = size_t(1) << 30;
constexpr int kTag = 7;

void check(int rc, const char* what) {
    if (rc != MPI_SUCCESS) throw InputError(std::string("MPI error in ") + what);
}

Bytes receiveBytes(int from) {
    uint64_t n = 0;
    check(MPI_Recv(&n, 1, MPI_UINT64_T, from, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    Bytes bytes(static_cast<size_t>(n));
    for (size_t at = 0; at < n; at += kPiece)
        check(MPI_Recv(bytes.data() + at, int(std::min(kPiece, size_t(n) - at)), MPI_BYTE, from,
                       kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
              "MPI_Recv");
    return bytes;
}

struct Pending {
    std::unique_ptr<uint64_t> size;  // the length message, sent first
    Bytes data;
    std::vector<MPI_Request> requests;
};
constexpr size_t kMaxPending = 64;

class MpiCluster final : public Cluster {
public:
    MpiCluster() {
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    ~MpiCluster() override {
        if (std::getenv("RADPHOTON_STATS"))
            std::fprintf(stderr, "mpi rank %d: sent %llu bytes in %llu messages\n", rank_,
                         (unsigned long long)sentBytes_, (unsigned long long)sentMessages_);
        while (!pending_.empty()) waitFront();
        MPI_Finalize();
    }

    int rank() const override { return rank_; }
    int size() const override { return size_; }

    void broadcast(Bytes& bytes) override {
        uint64_t n = bytes.size();
        if (rank_ == 0) {  // counted as the root sending to every other rank
            sentBytes_ += n * uint64_t(size_ - 1);
            sentMessages_ += uint64_t(size_ - 1);
        }
        check(MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
        bytes.resize(size_t(n));
        for (size_t at = 0; at < n; at += kPiece)
            check(MPI_Bcast(bytes.data() + at, int(std::min(kPiece, size_t(n) - at)), MPI_BYTE, 0,
                            MPI_COMM_WORLD),
                  "MPI_Bcast");
    }

    void send(int to, std::span<const std::byte> bytes) override { sendBytes(to, bytes); }
    Bytes receive(int from) override { return receiveBytes(from); }

    void abortAll(int exitCode) override { MPI_Abort(MPI_COMM_WORLD, exitCode); }

private:
    // Sends without waiting for the receiver, so that a rank goes on tracing while the root
    // is busy: a blocking send of a chunk (rendezvous protocol) held every rank in step
    // with the root's serial stage. At most kMaxPending messages are in flight; a copy of
    // each is kept until it has gone.
    void sendBytes(int to, std::span<const std::byte> bytes) {
        Pending p;
        p.size = std::make_unique<uint64_t>(bytes.size());
        p.data.assign(bytes.begin(), bytes.end());
        const size_t n = p.data.size();
        p.requests.emplace_back();
        check(
            MPI_Isend(p.size.get(), 1, MPI_UINT64_T, to, kTag, MPI_COMM_WORLD, &p.requests.back()),
            "MPI_Isend");
        for (size_t at = 0; at < n; at += kPiece) {
            p.requests.emplace_back();
            check(MPI_Isend(p.data.data() + at, int(std::min(kPiece, n - at)), MPI_BYTE, to, kTag,
                            MPI_COMM_WORLD, &p.requests.back()),
                  "MPI_Isend");
        }
        sentBytes_ += n;
        ++sentMessages_;
        pending_.push_back(std::move(p));
        while (!pending_.empty() && (pending_.size() > kMaxPending || done(pending_.front())))
            waitFront();
    }
    static bool done(Pending& p) {
        int flag = 0;
        check(MPI_Testall(int(p.requests.size()), p.requests.data(), &flag, MPI_STATUSES_IGNORE),
              "MPI_Testall");
        return flag != 0;
    }
    void waitFront() {
        Pending& p = pending_.front();
        check(MPI_Waitall(int(p.requests.size()), p.requests.data(), MPI_STATUSES_IGNORE),
              "MPI_Waitall");
        pending_.pop_front();
    }

    int rank_ = 0, size_ = 1;
    // What this rank sent (RADPHOTON_STATS prints it at the end: the communication volume
    // of bench/mpi_scaling.sh). Sends happen from one thread at a time.
    uint64_t sentBytes_ = 0, sentMessages_ = 0;
    std::deque<Pending> pending_;
};

}  // namespace

std::unique_ptr<Cluster> startMpiCluster(int& argc, char**& argv) {
    int provided = 0;
    if (MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS)
        throw InputError("cannot start MPI");
    if (provided < MPI_THREAD_SERIALIZED) {
        MPI_Finalize();
        throw InputError(
            "this MPI library cannot be called from more than one thread "
            "(MPI_THREAD_SERIALIZED)");
    }
    return std::make_unique<MpiCluster>();
}

}  // namespace rp
