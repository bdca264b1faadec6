// Temporary-file-and-rename output (see file_write.h).
#include "util/file_write.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include "util/error.h"

namespace rp {

void writeFileAtomically(const std::string& path, const std::string& data) {
    std::random_device rd;
    std::string tmp;
    int fd = -1;
    // O_EXCL makes the name ours even if another process writes next to us; mode 0666
    // lets the umask decide permissions as for any ordinary output file.
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, ".tmp%08x", static_cast<unsigned>(rd()));
        tmp = path + suffix;
        fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0)
        throw InputError(SourceLoc{path, 0},
                         std::string("cannot create output file: ") + std::strerror(errno));
    size_t done = 0;
    while (done < data.size()) {
        ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            int err = errno;
            ::close(fd);
            ::unlink(tmp.c_str());
            throw InputError(SourceLoc{path, 0}, std::string("write error: ") + std::strerror(err));
        }
        done += static_cast<size_t>(n);
    }
    // On the disk before the name points at it: a crash after the rename must not leave
    // a complete-looking name over a file whose data never arrived.
    if (::fsync(fd) != 0 || ::close(fd) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
        int err = errno;
        ::unlink(tmp.c_str());
        throw InputError(SourceLoc{path, 0}, std::string("cannot write: ") + std::strerror(err));
    }
    // And the rename itself (the folder's entry); failure here loses nothing written.
    const size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    int dfd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}

}  // namespace rp
