// Writing output files safely: a file is either written completely or not at all
// (STYLE.md, Errors). Its data goes to an unnamed file in the target's folder (Linux
// O_TMPFILE, so a killed run leaves nothing behind; a hidden temporary name where the
// file system lacks it), is synced to the disk, and only then takes the target's name.
// Used by pictures, PNG previews, scene files, meshes and photon maps; nothing here
// knows about file formats.
#pragma once

#include <cstddef>
#include <cstdint>
#include <streambuf>
#include <string>
#include <vector>

namespace rp {

class AtomicFile {
public:
    // Opens the unnamed file beside `path`. Throws InputError naming `path` when the
    // folder is not writable.
    explicit AtomicFile(std::string path);
    // Discards the data unless commit() succeeded.
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Whether the data has no name until commit() (O_TMPFILE): then a killed run leaves
    // nothing at all.
    bool unnamed() const { return tmpName_.empty() && !committed_; }
    // Writes all of data; throws InputError on a write error (disk full).
    void write(const void* data, size_t size);
    // Writes all of data at byte `offset` (the append position stays), for files whose
    // parts are produced out of order; several threads may write disjoint ranges at once.
    void writeAt(uint64_t offset, const void* data, size_t size);
    // Reads back `size` bytes at `offset` of what was written (InputError if it cannot).
    void readAt(uint64_t offset, void* data, size_t size) const;
    // Syncs the data, gives it the target's name (replacing an existing file unless
    // `replace` is false, when an existing target is an InputError) and syncs the folder.
    // `sync` false skips both syncs: for caches whose own checksum finds the torn file a
    // crash may leave, where waiting for the disk would cost more than the cache saves.
    void commit(bool replace = true, bool sync = true);

private:
    std::string path_;
    std::string tmpName_;  // only where O_TMPFILE was not available
    int fd_ = -1;
    bool committed_ = false;
};

// A stream buffer writing to an AtomicFile (std::ostream out(&buf)); flush() it before
// committing. Write errors surface as InputError from the stream's operations.
class AtomicFileBuf : public std::streambuf {
public:
    explicit AtomicFileBuf(AtomicFile& file) : file_(file), buffer_(1 << 16) {
        setp(buffer_.data(), buffer_.data() + buffer_.size());
    }
    // Writes what is buffered.
    void flush() {
        file_.write(pbase(), size_t(pptr() - pbase()));
        setp(buffer_.data(), buffer_.data() + buffer_.size());
    }

protected:
    int_type overflow(int_type c) override {
        flush();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override {
        flush();
        return 0;
    }

private:
    AtomicFile& file_;
    std::vector<char> buffer_;
};

// Reads exactly `size` bytes at byte `offset` of the open file `fd` (retrying short reads
// and EINTR). False, with errno set (0 at the end of the file), if they are not all there.
bool preadFully(int fd, uint64_t offset, void* data, size_t size);

// Writes `data` to `path` as an AtomicFile. Throws InputError naming `path` when the
// folder is not writable or the disk fills.
void writeFileAtomically(const std::string& path, const std::string& data);

}  // namespace rp
