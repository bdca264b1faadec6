// Photon records as mkpmap collects them, in collection order, within a memory budget:
// in memory as fixed-size chunks, or, once the records held by all stores sharing the
// budget would pass it, in an unnamed temporary file beside the map (util/temp_file.h).
// Why chunks rather than a std::vector: a vector that doubles holds the old and the new
// array at once (up to 3x the records), and a chunk's memory goes back to the system as
// soon as it has been consumed, so that moving the records on (into a kd-tree, or into
// the thinned map) never holds them twice. Building trees is kdtree.h / kdtree_external.h.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "util/bulk_memory.h"
#include "util/temp_file.h"

namespace rp::pmap {

// Bytes that stores may hold in memory, shared by all of a run's stores (mkpmap -aC).
// Thread-safe.
class MemoryBudget {
public:
    explicit MemoryBudget(uint64_t bytes) : limit_(bytes) {}
    MemoryBudget(const MemoryBudget&) = delete;
    MemoryBudget& operator=(const MemoryBudget&) = delete;

    // Takes `bytes` if they fit beside what is held; false (nothing taken) if not.
    bool take(uint64_t bytes) {
        uint64_t used = used_.load();
        do {
            if (used + bytes > limit_) return false;
        } while (!used_.compare_exchange_weak(used, used + bytes));
        return true;
    }
    void give(uint64_t bytes) { used_.fetch_sub(bytes); }
    uint64_t limit() const { return limit_; }
    uint64_t used() const { return used_.load(); }

private:
    uint64_t limit_;
    std::atomic<uint64_t> used_{0};
};

template <class Record>
class RecordStore {
public:
    // Records per chunk at most: 4 MiB (two huge pages, util/bulk_memory.h).
    static constexpr size_t kMaxChunkRecords = (size_t{4} << 20) / sizeof(Record);

    // In memory only, without a budget (tests, maps that must stay in memory).
    RecordStore() : chunkRecords_(kMaxChunkRecords) {}
    // Records beyond `budget` go to a temporary file in `folder`; errors name `what`.
    // Chunks are at most 1/16 of the budget, so that a small budget still holds records.
    RecordStore(MemoryBudget* budget, std::string folder, std::string what)
        : budget_(budget),
          folder_(std::move(folder)),
          what_(std::move(what)),
          chunkRecords_(
              std::clamp<size_t>(budget->limit() / 16 / sizeof(Record), 16, kMaxChunkRecords)) {}
    ~RecordStore() { freeChunks(); }
    RecordStore(RecordStore&& o) noexcept { *this = std::move(o); }
    RecordStore& operator=(RecordStore&& o) noexcept {
        if (this != &o) {
            freeChunks();
            budget_ = std::exchange(o.budget_, nullptr);
            folder_ = std::move(o.folder_);
            what_ = std::move(o.what_);
            chunkRecords_ = o.chunkRecords_;
            chunks_ = std::exchange(o.chunks_, {});
            tail_ = std::exchange(o.tail_, 0);
            size_ = std::exchange(o.size_, 0);
            file_ = std::exchange(o.file_, std::nullopt);
        }
        return *this;
    }

    void append(const Record& r) {
        if (chunks_.empty() || tail_ == chunkRecords_) nextChunk();
        ::new (static_cast<void*>(chunks_.back() + tail_++)) Record(r);  // raw chunk memory
        ++size_;
    }
    uint64_t size() const { return size_; }
    bool spilled() const { return file_.has_value(); }

    // Calls fn(std::span<const Record>) for all records in order, block by block.
    template <class Fn>
    void forEachBlock(Fn&& fn) const {
        if (file_) {
            std::vector<Record> block(kMaxChunkRecords);
            const uint64_t n = file_->size() / sizeof(Record);
            for (uint64_t i = 0; i < n; i += block.size()) {
                const size_t m = size_t(std::min<uint64_t>(block.size(), n - i));
                file_->readAt(i * sizeof(Record), block.data(), m * sizeof(Record));
                fn(std::span<const Record>(block.data(), m));
            }
        }
        for (size_t c = 0; c < chunks_.size(); ++c)
            fn(std::span<const Record>(chunks_[c], chunkSize(c)));
    }

    // A copy of all records (tests, small maps).
    std::vector<Record> toVector() const {
        std::vector<Record> v;
        v.reserve(size_);
        forEachBlock([&](std::span<const Record> b) { v.insert(v.end(), b.begin(), b.end()); });
        return v;
    }

    // As forEachBlock, each chunk's memory freed once fn has seen it; empty afterwards.
    template <class Fn>
    void drain(Fn&& fn) {
        forEachBlockFreeing(fn);
        *this = std::move(*this).emptied();
    }

    // All records in one array, each chunk freed once copied (peak: the records and one
    // chunk); a spilled store's are read back from its file. Empty afterwards. The array
    // is advised for huge pages before its first touch (util/bulk_memory.h).
    template <class Vector = BulkVector<Record>>
    Vector takeAll() {
        Vector all;
        all.reserve(size_);
        adviseHugePages(all.data(), size_ * sizeof(Record));
        forEachBlockFreeing(
            [&](std::span<const Record> b) { all.insert(all.end(), b.begin(), b.end()); });
        *this = std::move(*this).emptied();
        return all;
    }

    // The temporary file holding all records of a spilled store (what is buffered is
    // written first); the store is empty afterwards.
    TempFile takeFile() {
        flushBuffer();
        TempFile f = std::move(*file_);
        *this = std::move(*this).emptied();
        return f;
    }

private:
    size_t chunkSize(size_t c) const { return c + 1 == chunks_.size() ? tail_ : chunkRecords_; }
    uint64_t chunkBytes() const { return uint64_t(chunkRecords_) * sizeof(Record); }

    // A fresh chunk (in memory while the budget allows); once spilled, the one chunk left
    // is a write buffer, emptied into the file when full.
    void nextChunk() {
        if (file_) {
            flushBuffer();
            return;
        }
        if (budget_ && !budget_->take(chunkBytes())) {
            spill();
            return;
        }
        chunks_.push_back(BulkAllocator<Record>().allocate(chunkRecords_));
        tail_ = 0;
    }

    // Moves every chunk to a new temporary file and keeps one as the write buffer, which
    // the budget no longer counts (at most 1/16 of it).
    void spill() {
        TempFile file(folder_, what_);
        for (size_t c = 0; c < chunks_.size(); ++c)
            file.append(chunks_[c], chunkSize(c) * sizeof(Record));
        while (chunks_.size() > 1) freeChunk(chunks_.size() - 1);
        if (chunks_.empty())
            chunks_.push_back(BulkAllocator<Record>().allocate(chunkRecords_));
        else
            budget_->give(chunkBytes());
        file_.emplace(std::move(file));
        tail_ = 0;
    }

    void flushBuffer() {
        if (!chunks_.empty()) file_->append(chunks_[0], tail_ * sizeof(Record));
        tail_ = 0;
    }

    template <class Fn>
    void forEachBlockFreeing(Fn&& fn) {
        if (file_) {
            flushBuffer();
            freeChunks();
            forEachBlock(fn);
            return;
        }
        for (size_t c = 0; c < chunks_.size(); ++c) {
            fn(std::span<const Record>(chunks_[c], chunkSize(c)));
            BulkAllocator<Record>().deallocate(chunks_[c], chunkRecords_);
            chunks_[c] = nullptr;
            if (budget_) budget_->give(chunkBytes());
        }
        chunks_.clear();
        tail_ = 0;
    }

    // A store with the same budget and folder and nothing in it.
    RecordStore emptied() && {
        RecordStore s;
        s.budget_ = budget_;
        s.folder_ = folder_;
        s.what_ = what_;
        s.chunkRecords_ = chunkRecords_;
        return s;
    }

    // Frees chunk c, the last; in memory (not spilled), the budget had counted it.
    void freeChunk(size_t c) {
        if (chunks_[c]) BulkAllocator<Record>().deallocate(chunks_[c], chunkRecords_);
        chunks_.erase(chunks_.begin() + std::ptrdiff_t(c));
        if (budget_ && !file_) budget_->give(chunkBytes());
    }
    void freeChunks() {
        while (!chunks_.empty()) freeChunk(chunks_.size() - 1);
        tail_ = 0;
    }

    MemoryBudget* budget_ = nullptr;
    std::string folder_, what_;
    size_t chunkRecords_ = kMaxChunkRecords;
    std::vector<Record*> chunks_;
    size_t tail_ = 0;  // records in the last chunk
    uint64_t size_ = 0;
    std::optional<TempFile> file_;
};

}  // namespace rp::pmap
