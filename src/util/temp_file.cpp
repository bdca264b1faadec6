// Unnamed scratch files (see temp_file.h).
#include "util/temp_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <utility>

#include "util/error.h"

namespace rp {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& message, int err) {
    throw InputError(SourceLoc{what, 0}, message + ": " + std::strerror(err));
}

// A named scratch file, removed from the folder as soon as it is open (the data lives on
// until the descriptor is closed), for file systems without O_TMPFILE.
int openUnlinked(const std::string& folder) {
    std::random_device rd;
    for (int attempt = 0; attempt < 100; ++attempt) {
        char name[32];
        std::snprintf(name, sizeof name, "/.rp_scratch.%08x.tmp", static_cast<unsigned>(rd()));
        const std::string path = folder + name;
        int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (fd >= 0) {
            ::unlink(path.c_str());
            return fd;
        }
        if (errno != EEXIST) return -1;
    }
    errno = EEXIST;
    return -1;
}

}  // namespace

std::string folderOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

TempFile::TempFile(const std::string& folder, std::string what) : what_(std::move(what)) {
#ifdef O_TMPFILE
    fd_ = ::open(folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
#endif
    if (fd_ < 0) fd_ = openUnlinked(folder);
    if (fd_ < 0) fail(what_, "cannot create a temporary file in " + folder, errno);
}

TempFile::~TempFile() { close(); }

TempFile::TempFile(TempFile&& o) noexcept
    : what_(std::move(o.what_)), fd_(std::exchange(o.fd_, -1)), size_(std::exchange(o.size_, 0)) {}

TempFile& TempFile::operator=(TempFile&& o) noexcept {
    if (this != &o) {
        close();
        what_ = std::move(o.what_);
        fd_ = std::exchange(o.fd_, -1);
        size_ = std::exchange(o.size_, 0);
    }
    return *this;
}

void TempFile::close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    size_ = 0;
}

void TempFile::append(const void* data, size_t bytes) {
    const char* p = static_cast<const char*>(data);
    while (bytes > 0) {
        const ssize_t n = ::write(fd_, p, bytes);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            fail(what_, "error writing a temporary file (disk full?)", n < 0 ? errno : ENOSPC);
        p += n;
        bytes -= size_t(n);
        size_ += uint64_t(n);
    }
}

void TempFile::readAt(uint64_t offset, void* data, size_t bytes) const {
    char* p = static_cast<char*>(data);
    while (bytes > 0) {
        const ssize_t n = ::pread(fd_, p, bytes, off_t(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail(what_, "error reading a temporary file", errno);
        if (n == 0) throw InputError(SourceLoc{what_, 0}, "temporary file shorter than written");
        p += n;
        bytes -= size_t(n);
        offset += uint64_t(n);
    }
}

void TempFile::clear() {
    if (::ftruncate(fd_, 0) != 0 || ::lseek(fd_, 0, SEEK_SET) != 0)
        fail(what_, "cannot truncate a temporary file", errno);
    size_ = 0;
}

}  // namespace rp
