// Output files written completely or not at all (see file_write.h).
#include "util/file_write.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include "util/error.h"
#include "util/temp_file.h"

namespace rp {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
    throw InputError(SourceLoc{path, 0}, what + ": " + std::strerror(err));
}

// A fresh name beside `path` that nobody else holds (O_EXCL), opened for writing.
int openNamedTemporary(const std::string& path, std::string& name) {
    std::random_device rd;
    const std::string folder = folderOf(path);
    const std::string base = path.substr(path.find_last_of('/') + 1);
    for (int attempt = 0; attempt < 100; ++attempt) {
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, ".%08x.tmp", static_cast<unsigned>(rd()));
        name = folder + "/." + base + suffix;
        // Mode 0666: the umask decides, as for any ordinary output file.
        int fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    errno = EEXIST;
    return -1;
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
#ifdef O_TMPFILE
    fd_ = ::open(folderOf(path_).c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
#endif
    // Some file systems (and old kernels) have no unnamed files: a hidden name then,
    // removed again on failure (a killed run can leave it, named ".<target>.*.tmp").
    if (fd_ < 0) fd_ = openNamedTemporary(path_, tmpName_);
    if (fd_ < 0) fail(path_, "cannot create output file", errno);
}

AtomicFile::~AtomicFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_ && !tmpName_.empty()) ::unlink(tmpName_.c_str());
}

void AtomicFile::write(const void* data, size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        ssize_t n = ::write(fd_, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(path_, "write error", n < 0 ? errno : ENOSPC);
        p += n;
        size -= size_t(n);
    }
}

void AtomicFile::writeAt(uint64_t offset, const void* data, size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        ssize_t n = ::pwrite(fd_, p, size, off_t(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(path_, "write error", n < 0 ? errno : ENOSPC);
        p += n;
        size -= size_t(n);
        offset += uint64_t(n);
    }
}

void AtomicFile::readAt(uint64_t offset, void* data, size_t size) const {
    if (!preadFully(fd_, offset, data, size)) fail(path_, "read error", errno ? errno : EIO);
}

bool preadFully(int fd, uint64_t offset, void* data, size_t size) {
    char* p = static_cast<char*>(data);
    while (size > 0) {
        ssize_t n = ::pread(fd, p, size, off_t(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = 0;
            return false;
        }
        p += n;
        size -= size_t(n);
        offset += uint64_t(n);
    }
    return true;
}

void AtomicFile::commit(bool replace, bool sync) {
    // On the disk before the name points at it: a crash after the rename must not leave
    // a complete-looking name over a file whose data never arrived.
    if (sync && ::fsync(fd_) != 0) fail(path_, "cannot write", errno);
    if (tmpName_.empty()) {
        // An unnamed file gets a name through /proc (linkat without privileges), a
        // hidden one for the instant before the rename.
        char proc[64];
        std::snprintf(proc, sizeof proc, "/proc/self/fd/%d", fd_);
        int err = 0;
        for (int attempt = 0; attempt < 100; ++attempt) {
            std::random_device rd;
            char suffix[32];
            std::snprintf(suffix, sizeof suffix, ".%08x.tmp", static_cast<unsigned>(rd()));
            tmpName_ = folderOf(path_) + "/." + path_.substr(path_.find_last_of('/') + 1) + suffix;
            if (::linkat(AT_FDCWD, proc, AT_FDCWD, tmpName_.c_str(), AT_SYMLINK_FOLLOW) == 0) {
                err = 0;
                break;
            }
            err = errno;
            if (err != EEXIST) break;
        }
        if (err != 0) {
            tmpName_.clear();
            fail(path_, "cannot write", err);
        }
    }
    if (!replace && ::access(path_.c_str(), F_OK) == 0)
        throw InputError(SourceLoc{path_, 0}, "file exists (not replaced)");
    if (std::rename(tmpName_.c_str(), path_.c_str()) != 0) fail(path_, "cannot write", errno);
    committed_ = true;
    if (!sync) return;
    // And the rename itself (the folder's entry); failure here loses nothing written.
    int dfd = ::open(folderOf(path_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}

void writeFileAtomically(const std::string& path, const std::string& data) {
    AtomicFile f(path);
    f.write(data.data(), data.size());
    f.commit();
}

}  // namespace rp
