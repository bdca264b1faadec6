// A cluster of threads for tests: `runRanks(n, body)` runs body(cluster) on n threads,
// each a rank of one in-process cluster whose messages go through mailboxes. It lets the
// library's rank splitting (mkpmap's chunks, rtrace's slices) be tested without MPI.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "util/cluster.h"

namespace rp::testing {

class ThreadCluster {
public:
    explicit ThreadCluster(int ranks) : ranks_(ranks), boxes_(size_t(ranks) * size_t(ranks)) {}

    void post(int from, int to, Bytes bytes) {
        Box& b = box(from, to);
        std::lock_guard<std::mutex> lock(b.mutex);
        b.messages.push_back(std::move(bytes));
        b.ready.notify_one();
    }
    Bytes take(int from, int to) {
        Box& b = box(from, to);
        std::unique_lock<std::mutex> lock(b.mutex);
        b.ready.wait(lock, [&] { return !b.messages.empty(); });
        Bytes bytes = std::move(b.messages.front());
        b.messages.pop_front();
        return bytes;
    }
    int ranks() const { return ranks_; }

private:
    struct Box {
        std::mutex mutex;
        std::condition_variable ready;
        std::deque<Bytes> messages;
    };
    Box& box(int from, int to) { return boxes_[size_t(from) * size_t(ranks_) + size_t(to)]; }
    int ranks_;
    std::vector<Box> boxes_;
};

// One rank's view of a ThreadCluster.
class ThreadRank final : public Cluster {
public:
    ThreadRank(ThreadCluster& c, int rank) : c_(c), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return c_.ranks(); }
    void broadcast(Bytes& bytes) override {
        if (rank_ == 0) {
            for (int r = 1; r < size(); ++r) c_.post(0, r, bytes);
        } else {
            bytes = c_.take(0, rank_);
        }
    }
    void send(int to, std::span<const std::byte> bytes) override {
        c_.post(rank_, to, Bytes(bytes.begin(), bytes.end()));
    }
    Bytes receive(int from) override { return c_.take(from, rank_); }
    void abortAll(int) override { std::terminate(); }

private:
    ThreadCluster& c_;
    int rank_;
};

// Runs body(rank) for ranks 0..n-1 on threads of their own; rethrows the first exception.
inline void runRanks(int n, const std::function<void(Cluster&)>& body) {
    ThreadCluster cluster(n);
    std::vector<std::exception_ptr> errors(static_cast<size_t>(n));
    std::vector<std::thread> threads;
    for (int r = 0; r < n; ++r)
        threads.emplace_back([&, r] {
            ThreadRank rank(cluster, r);
            try {
                body(rank);
            } catch (...) {
                errors[size_t(r)] = std::current_exception();
            }
        });
    for (auto& t : threads) t.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
}

}  // namespace rp::testing
