// Scratch files for data that does not fit in memory (mkpmap's spilled photons and the
// parts of an external kd-tree build). Nothing here knows about photons; output files
// that must appear whole are file_write.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace rp {

// An unnamed file in `folder` (Linux O_TMPFILE; where the file system lacks it, a named
// one unlinked at once), so that it is gone on every exit path: normal end, exception,
// crash or kill. Errors are InputErrors naming `what` (the output the data belongs to).
// Appends go through the file's offset; reads are positional (pread), so several threads
// may read one file at once.
class TempFile {
public:
    TempFile(const std::string& folder, std::string what);
    ~TempFile();
    TempFile(TempFile&& o) noexcept;
    TempFile& operator=(TempFile&& o) noexcept;
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;

    // Appends all of data; InputError on a write error ("disk full?").
    void append(const void* data, size_t bytes);
    // Reads exactly `bytes` at `offset`; InputError if the file holds fewer.
    void readAt(uint64_t offset, void* data, size_t bytes) const;
    uint64_t size() const { return size_; }
    // Empties the file and returns its blocks to the file system.
    void clear();

private:
    void close();

    std::string what_;
    int fd_ = -1;
    uint64_t size_ = 0;
};

// The folder part of `path` ("." when it has none), where scratch files for an output
// written to `path` belong (same file system, so that the space check is the real one).
std::string folderOf(const std::string& path);

}  // namespace rp
