// The -af ambient file (see ambient_file.h).
#include "render/ambient_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "util/error.h"
#include "util/header.h"

namespace rp::render {

namespace {

template <typename T>
void put(unsigned char*& p, T v) {
    static_assert(sizeof(T) == 4 || sizeof(T) == 8);
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::big)
        for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    std::memcpy(p, b, sizeof(T));
    p += sizeof(T);
}

template <typename T>
T get(const unsigned char*& p) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, p, sizeof(T));
    if constexpr (std::endian::native == std::endian::big)
        for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    T v;
    std::memcpy(&v, b, sizeof(T));
    p += sizeof(T);
    return v;
}

void putVecF(unsigned char*& p, const Vec3& v) {
    for (int i = 0; i < 3; ++i) put<float>(p, float(v[i]));
}
Vec3 getVecF(const unsigned char*& p) {
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = get<float>(p);
    return v;
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

Header makeHeader(const std::string& options, const std::string& bands) {
    Header h;
    h.lines.push_back("radphoton ambient values (irradiance cache records)");
    h.lines.push_back("AMBIENT_OPTIONS=" + options);
    if (!bands.empty()) h.lines.push_back("BANDS=" + bands);
    h.lines.push_back(fmt::format("RECORD_BYTES={}", kAmbientRecordBytes));
    h.lines.push_back("BYTE_ORDER=little");
    h.lines.push_back(std::string("FORMAT=") + kAmbientFormat);
    return h;
}

// Checks the header of an open ambient file; `bytes` receives its record size. Throws
// InputError naming `path`.
Header checkHeader(std::istream& in, const std::string& path, size_t& bytes) {
    Header h = readHeader(in, path);
    SourceLoc loc{path, 0};
    if (h.format() != kAmbientFormat)
        throw InputError(loc,
                         fmt::format("not an ambient file (FORMAT={}, expected {})",
                                     h.format().empty() ? "none" : h.format(), kAmbientFormat));
    const std::string size = h.value("RECORD_BYTES");
    if (size == std::to_string(kAmbientRecordBytes))
        bytes = kAmbientRecordBytes;
    else if (size == std::to_string(kLegacyAmbientRecordBytes))
        bytes = kLegacyAmbientRecordBytes;
    else
        throw InputError(loc, fmt::format("ambient records of {} bytes, expected {}", size,
                                          kAmbientRecordBytes));
    if (h.value("BYTE_ORDER") != "little")
        throw InputError(loc, "ambient file byte order is not 'little'");
    return h;
}

}  // namespace

std::string bandsProblem(const std::string& file, const std::string& run) {
    auto name = [](const std::string& b) { return b.empty() ? std::string("RGB") : b; };
    return "ambient file of " + name(file) + ", not of this run's " + name(run);
}

std::string ambientFileOptions(const AmbientOptions& o) {
    return fmt::format("-aa {} -ar {} -ad {} -as {} -ab {}", o.accuracy, o.resolution, o.divisions,
                       o.supersamples, o.bounces);
}

void encodeAmbientRecord(const AmbientRecord& r, unsigned char* out, size_t bytes) {
    unsigned char* p = out;
    for (int i = 0; i < 3; ++i) put<double>(p, r.position[i]);
    putVecF(p, r.normal);
    for (int i = 0; i < 3; ++i) put<float>(p, float(r.value[i]));
    put<float>(p, float(r.radius));
    putVecF(p, r.gradPosition);
    putVecF(p, r.gradDirection);
    put<float>(p, float(r.weight));
    put<int32_t>(p, int32_t(r.level));
    if (bytes == kAmbientRecordBytes) put<uint32_t>(p, r.corral);
    RP_CHECK(size_t(p - out) == bytes);
}

AmbientRecord decodeAmbientRecord(const unsigned char* in, size_t bytes) {
    const unsigned char* p = in;
    AmbientRecord r;
    for (int i = 0; i < 3; ++i) r.position[i] = get<double>(p);
    r.normal = getVecF(p);
    for (int i = 0; i < 3; ++i) r.value[i] = get<float>(p);
    r.radius = get<float>(p);
    r.gradPosition = getVecF(p);
    r.gradDirection = getVecF(p);
    r.weight = get<float>(p);
    r.level = get<int32_t>(p);
    if (bytes == kAmbientRecordBytes) r.corral = get<uint32_t>(p);
    return r;
}

AmbientFileContents readAmbientFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, "can't open ambient file");
    size_t bytes = 0;
    const Header h = checkHeader(in, path, bytes);
    AmbientFileContents out;
    out.options = h.value("AMBIENT_OPTIONS");
    out.bands = h.value("BANDS");
    std::vector<unsigned char> data((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    if (data.size() % bytes != 0)
        throw InputError(SourceLoc{path, 0},
                         fmt::format("truncated ambient file: {} bytes after the {} whole "
                                     "records",
                                     data.size() % bytes, data.size() / bytes));
    size_t n = data.size() / bytes;
    out.records.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        AmbientRecord r = decodeAmbientRecord(data.data() + i * bytes, bytes);
        double nl = length(r.normal);
        bool ok = finite(r.position) && finite(r.normal) && finite(r.gradPosition) &&
                  finite(r.gradDirection) && std::isfinite(r.value.r) && std::isfinite(r.value.g) &&
                  std::isfinite(r.value.b) && std::isfinite(r.radius) && r.radius > 0 &&
                  std::isfinite(r.weight) && r.level >= 0 && std::fabs(nl - 1) < 1e-3;
        if (!ok)
            throw InputError(SourceLoc{path, 0},
                             fmt::format("corrupt ambient record {} of {}", i + 1, n));
        r.normal = r.normal / nl;
        out.records.push_back(r);
    }
    return out;
}

namespace {

// Appends `data` under an exclusive lock with whole write() calls, so renderers sharing
// one file (rad -N, RADIANCE's practice) neither interleave nor tear records.
void appendLocked(const std::string& path, const std::vector<unsigned char>& data) {
    const SourceLoc loc{path, 0};
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND);
    if (fd < 0) throw InputError(loc, "can't open ambient file");
    ::flock(fd, LOCK_EX);
    size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += size_t(n);
    }
    ::flock(fd, LOCK_UN);
    if (::close(fd) != 0 || done < data.size())
        throw InputError(loc, "error writing to ambient file");
}

}  // namespace

void appendAmbientFile(const std::string& path, const std::string& options,
                       const std::vector<AmbientRecord>& records, const std::string& bands) {
    SourceLoc loc{path, 0};
    auto encode = [&](size_t bytes) {
        std::vector<unsigned char> data(records.size() * bytes);
        for (size_t i = 0; i < records.size(); ++i)
            encodeAmbientRecord(records[i], data.data() + i * bytes, bytes);
        return data;
    };
    auto appendToExisting = [&] {
        size_t bytes = 0;
        {
            std::ifstream in(path, std::ios::binary);
            if (!in) throw InputError(loc, "can't open ambient file");
            const Header h = checkHeader(in, path, bytes);  // a legacy file keeps its record size
            if (h.value("BANDS") != bands)
                throw InputError(loc, bandsProblem(h.value("BANDS"), bands));
        }
        appendLocked(path, encode(bytes));
    };
    if (std::filesystem::exists(path)) return appendToExisting();
    // A new file is written aside and linked into place (a crash leaves no half header);
    // if another process made it meanwhile, the records go at its end instead.
    const std::vector<unsigned char> data = encode(kAmbientRecordBytes);
    std::string tmp = fmt::format("{}.{}.tmp", path, ::getpid());
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw InputError(loc, "can't create ambient file");
        writeHeader(out, makeHeader(options, bands));
        out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            throw InputError(loc, "error writing to ambient file");
        }
    }
    const int linkError = ::link(tmp.c_str(), path.c_str()) == 0 ? 0 : errno;
    if (linkError == 0 || linkError == EEXIST) {
        std::remove(tmp.c_str());
        if (linkError == EEXIST) appendToExisting();
        return;
    }
    // A file system without hard links: renamed into place as before.
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        std::remove(tmp.c_str());
        throw InputError(loc, fmt::format("can't create ambient file: {}", std::strerror(err)));
    }
}

}  // namespace rp::render
