// RADIANCE photon map files, format "3.1k" (pmapio.c savePhotonMap/loadPhotonMap and
// pmapkdt.c kdT_SavePhotons/kdT_LoadPhotons): info header, then in portable encoding
//   version string (NUL-terminated), numPhotons (8 B), avg flux (3 flt), bbox interleaved
//   min0,max0,min1,max1,min2,max2 (6 flt), CoG (3 flt), CoGdist (1 flt), numPrimary (4 B),
//   primaries (srcIdx 2 B each; "3.1kPD": srcIdx 2 B, direction code 4 B, position 3 flt,
//   21 B), photons in kd-tree order, 27 B each:
//   pos 3 flt | norm 3 x 1 B | RGBE 4 x 1 B | primary 4 B | flags 1 B.
#include <fcntl.h>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <random>
#include <sstream>

#include "pmap/photon_map.h"
#include "pmap/photon_records.h"
#include "pmap/record_checksums.h"
#include "util/bulk_memory.h"
#include "util/error.h"
#include "util/file_write.h"

namespace rp::pmap {

using portable::ByteReader;
using portable::getFlt;
using portable::getInt;
using portable::getInt32;
using portable::kPortableFloatSize;
using portable::putFlt;
using portable::putInt;
using portable::putStr;

namespace {

constexpr size_t kPrimaryRecordSize = 2;
constexpr size_t kPrimaryRayRecordSize = 2 + 4 + 3 * kPortableFloatSize;  // 3.1kPD
// Bytes after the version string up to and including numPrimary.
constexpr size_t kFixedBinarySize = 8 + (3 + 6 + 3 + 1) * kPortableFloatSize + 4;  // 77
constexpr size_t kMaxVersionLength = 32;
constexpr size_t kChunkPhotons = size_t{1} << 16;  // photons decoded per task (/ 4)
// Photons encoded per write buffer: 442 kB, so the four buffers of a save come from the
// heap, reused from one save to the next. At 2^16 photons each buffer was a fresh 2 MB
// huge page, 16 MB zero-filled by the kernel per mkpmap run.
constexpr size_t kWriteChunkPhotons = size_t{1} << 14;
constexpr size_t kReadChunkPhotons = size_t{1} << 18;  // photons read per chunk (7 MB)

std::string cFormat(const char* format, auto... args) {
    char buf[256];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

// Explains why a version string other than "3.1k" cannot be read.
std::string versionProblem(const std::string& v) {
    if (v.rfind("3.1o", 0) == 0)
        return "out-of-core photon maps not supported yet (VERSION=" + v + ")";
    if (v.rfind("3.1k", 0) == 0 && v.find_first_not_of("fPD", 4) == std::string::npos)
        return "photon map file version " + v +
               " not supported yet (3.1k and 3.1kPD only: RGBE flux, primaries with neither "
               "or both of position 'P' and direction 'D')";
    return "incompatible photon map file version '" + v + "' (expected " + kPhotonMapFileVersion +
           " or " + kPhotonMapFileVersionPD + ")";
}

bool knownVersion(const std::string& v) {
    return v == kPhotonMapFileVersion || v == kPhotonMapFileVersionPD;
}

// Identifies the map type from the FORMAT line; throws for anything but a kd-tree map.
PhotonMapType typeFromFormat(const std::string& format, const SourceLoc& loc) {
    const std::string prefix = "Radiance_", suffix = "_Photon_Map";
    if (format.empty()) throw InputError(loc, "not a photon map (no FORMAT line in header)");
    if (format.size() < prefix.size() + suffix.size() || format.rfind(prefix, 0) != 0 ||
        format.compare(format.size() - suffix.size(), suffix.size(), suffix) != 0)
        throw InputError(loc, "not a photon map (FORMAT=" + format + ")");
    std::string middle =
        format.substr(prefix.size(), format.size() - prefix.size() - suffix.size());
    auto endsWith = [&](const char* s) {
        const size_t n = std::strlen(s);
        return middle.size() > n && middle.compare(middle.size() - n, n, s) == 0;
    };
    if (endsWith("_OOC"))
        throw InputError(loc, "out-of-core photon maps not supported yet (FORMAT=" + format + ")");
    if (!endsWith("_kdT"))
        throw InputError(loc, "unsupported photon map format " + format + " (expected Radiance_" +
                                  "<type>_kdT_Photon_Map, RADIANCE 5.4 and later)");
    const std::string name = middle.substr(0, middle.size() - 4);
    auto type = photonMapTypeFromName(name);
    if (!type)
        throw InputError(loc, "unknown photon map type '" + name + "' (FORMAT=" + format + ")");
    return *type;
}

bool readBytes(std::istream& in, void* dst, size_t n) {
    in.read(static_cast<char*>(dst), static_cast<std::streamsize>(n));
    return static_cast<size_t>(in.gcount()) == n;
}

}  // namespace

void encodePhoton(unsigned char* out, const Photon& p) {
    for (int a = 0; a < 3; ++a) putFlt(out + a * kPortableFloatSize, p.pos[a]);
    out += 3 * kPortableFloatSize;
    for (int a = 0; a < 3; ++a) out[a] = static_cast<unsigned char>(p.norm[a]);
    for (int a = 0; a < 4; ++a) out[3 + a] = p.flux[a];
    putInt(out + 7, p.primary, 4);
    out[11] = p.flags;
}

const char* PhotonMapFileInfo::fileVersion() const {
    return primaryRays.empty() ? kPhotonMapFileVersion : kPhotonMapFileVersionPD;
}

const char* PhotonMap::fileVersion() const { return fileInfo().fileVersion(); }

PhotonMapFileInfo PhotonMap::fileInfo() const {
    PhotonMapFileInfo info;
    info.type = type_;
    info.stats = stats_;
    info.primaries = primaries_;
    info.primaryRays = primaryRays_;
    info.bands = bands_;
    return info;
}

Header PhotonMap::fileHeader(const std::string& commandLine) const {
    return photonMapFileHeader(fileInfo(), commandLine);
}

Header photonMapFileHeader(const PhotonMapFileInfo& info, const std::string& commandLine) {
    Header h;
    std::string cmd = commandLine;
    for (char& c : cmd)
        if (c == '\n' || c == '\r') c = ' ';  // a newline would end the header early
    if (!cmd.empty()) h.lines.push_back(cmd);
    const PhotonMapStats& s = info.stats;
    // RADIANCE compat: the exact fprintf formats of savePhotonMap (floats promoted to double).
    h.lines.push_back(cFormat("NumPhotons\t= %llu", static_cast<unsigned long long>(s.numPhotons)));
    h.lines.push_back(cFormat("AvgFlux\t\t= [%.2e, %.2e, %.2e]", double(s.avgFlux[0]),
                              double(s.avgFlux[1]), double(s.avgFlux[2])));
    h.lines.push_back(cFormat("Bbox\t\t= [%.3f, %.3f, %.3f] [%.3f, %.3f, %.3f]",
                              double(s.bboxMin[0]), double(s.bboxMin[1]), double(s.bboxMin[2]),
                              double(s.bboxMax[0]), double(s.bboxMax[1]), double(s.bboxMax[2])));
    h.lines.push_back(cFormat("CoG\t\t= [%.3f, %.3f, %.3f]", s.cog[0], s.cog[1], s.cog[2]));
    // RADIANCE compat: labelled MaxDist^2 but the value is CoGdist.
    h.lines.push_back(cFormat("MaxDist^2\t= %.3f", double(s.cogDist2)));
    if (!info.primaries.empty())
        h.lines.push_back(cFormat("%u primary rays", static_cast<unsigned>(info.primaries.size())));
    if (info.bands) {
        const spectral::Sampling& sp = info.bands->sampling;
        h.lines.push_back(fmt::format("NCOMP={}", sp.n));
        h.lines.push_back(fmt::format("WAVELENGTH_SPLITS= {:g} {:g} {:g} {:g}", sp.wl[0], sp.wl[1],
                                      sp.wl[2], sp.wl[3]));
        h.lines.push_back(fmt::format("BANDS= {} {}", info.bands->first,
                                      std::min(info.bands->first + 2, sp.n - 1)));
    }
    h.lines.push_back("FORMAT=" + photonMapFormat(info.type));
    h.lines.push_back(std::string("VERSION=") + info.fileVersion());
    if (info.checksumBlock)
        h.lines.push_back(fmt::format("{}={}", kChecksumKey, info.checksumBlock));
    return h;
}

std::string photonMapFilePrologue(const PhotonMapFileInfo& info, const std::string& commandLine) {
    std::ostringstream text;
    writeHeader(text, photonMapFileHeader(info, commandLine));
    std::string b = text.str();
    const PhotonMapStats& s = info.stats;
    putStr(b, info.fileVersion());
    putInt(b, static_cast<int64_t>(s.numPhotons), 8);
    for (int a = 0; a < 3; ++a) putFlt(b, s.avgFlux[a]);
    for (int a = 0; a < 3; ++a) {
        putFlt(b, s.bboxMin[a]);
        putFlt(b, s.bboxMax[a]);
    }
    for (int a = 0; a < 3; ++a) putFlt(b, s.cog[a]);
    putFlt(b, s.cogDist2);
    putInt(b, static_cast<int64_t>(info.primaries.size()), 4);
    for (size_t i = 0; i < info.primaries.size(); ++i) {
        putInt(b, info.primaries[i].srcIdx, 2);
        if (info.primaryRays.empty()) continue;
        // RADIANCE compat (pmapio.c): the direction before the position.
        const PrimaryRay& r = info.primaryRays[i];
        putInt(b, r.dir, 4);
        for (int a = 0; a < 3; ++a) putFlt(b, r.pos[size_t(a)]);
    }
    return b;
}

void PhotonMap::write(std::ostream& out, const std::string& commandLine) const {
    const std::span<const Photon> photons = this->photons();  // all of a map read on demand
    RP_CHECK(photons.size() == stats_.numPhotons);
    // Every map radphoton writes carries record checksums (record_checksums.h); each
    // written chunk is whole checksum blocks but the last.
    static_assert(kWriteChunkPhotons % kChecksumBlock == 0);
    PhotonMapFileInfo info = fileInfo();
    info.checksumBlock = kChecksumBlock;
    const std::string b = photonMapFilePrologue(info, commandLine);
    out.write(b.data(), static_cast<std::streamsize>(b.size()));
    RecordChecksums sums;
    sums.block = kChecksumBlock;
    // Chunks are encoded in parallel (in the caller's task arena), a batch at a time to
    // bound the buffer memory, and written in order: the bytes do not depend on threads.
    // BulkVectors: resize() leaves them uninitialised (each byte is written once).
    constexpr size_t kBatch = 4;
    BulkVector<unsigned char> bufs[kBatch];
    const size_t n = photons.size();
    for (size_t i = 0; i < n; i += kBatch * kWriteChunkPhotons) {
        const size_t chunks =
            std::min(kBatch, (n - i + kWriteChunkPhotons - 1) / kWriteChunkPhotons);
        tbb::parallel_for(size_t{0}, chunks, [&](size_t k) {
            BulkVector<unsigned char>& buf = bufs[k];
            const size_t begin = i + k * kWriteChunkPhotons;
            const size_t end = std::min(n, begin + kWriteChunkPhotons);
            buf.resize((end - begin) * kPhotonRecordSize);
            unsigned char* b = buf.data();
            for (size_t j = begin; j < end; ++j, b += kPhotonRecordSize)
                encodePhoton(b, photons[j]);
        });
        for (size_t k = 0; k < chunks; ++k) {
            const size_t bytes = bufs[k].size();
            constexpr size_t kBlockBytes = kChecksumBlock * kPhotonRecordSize;
            for (size_t at = 0; at < bytes; at += kBlockBytes)
                sums.crc.push_back(
                    recordsChecksum(bufs[k].data() + at, std::min(kBlockBytes, bytes - at)));
            out.write(reinterpret_cast<const char*>(bufs[k].data()),
                      static_cast<std::streamsize>(bytes));
        }
    }
    const std::string trailer = sums.encode();
    out.write(trailer.data(), static_cast<std::streamsize>(trailer.size()));
}

void PhotonMap::save(const std::string& path, const std::string& commandLine,
                     bool overwrite) const {
    namespace fs = std::filesystem;
    const SourceLoc loc{path, 0};
    if (empty()) throw InputError(loc, "refusing to save an empty photon map");
    std::error_code ec;
    if (!overwrite && fs::exists(path, ec))
        throw InputError(loc, "photon map file exists; use -fo to overwrite it");

    // Written completely or not at all, and a killed run leaves no temporary file.
    AtomicFile file(path);
    AtomicFileBuf buf(file);
    std::ostream out(&buf);
    out.exceptions(std::ios::badbit);
    try {
        write(out, commandLine);
        out.flush();
    } catch (const std::ios_base::failure&) {
        throw InputError(loc, "error writing photon map (disk full?)");
    }
    file.commit(overwrite);
}

Photon decodePhoton(const unsigned char* b) {
    Photon p;
    // RADIANCE compat: getflt's double is assigned to the float position (round to nearest).
    for (int a = 0; a < 3; ++a) p.pos[a] = static_cast<float>(getFlt(b + a * kPortableFloatSize));
    b += 3 * kPortableFloatSize;
    for (int a = 0; a < 3; ++a) p.norm[a] = static_cast<int8_t>(b[a]);
    for (int a = 0; a < 4; ++a) p.flux[a] = b[3 + a];
    p.primary = static_cast<uint32_t>(getInt32(b + 7));
    p.flags = b[11];
    return p;
}

void decodePhotons(const unsigned char* src, size_t n, Photon* dst) {
    tbb::this_task_arena::isolate([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kChunkPhotons / 4),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t j = r.begin(); j < r.end(); ++j)
                                  dst[j] = decodePhoton(src + j * kPhotonRecordSize);
                          });
    });
}

std::string treeProblem(const std::string& problem) {
    return "photons are not a valid kd-tree (" + problem + "); corrupt file?";
}

void PhotonMap::checkTreeOrder(const std::string& what) const {
    // read() has checked every record already (and built maps have valid ones).
    const std::string problem = checkKdTreeOrder(photons());
    if (!problem.empty()) throw InputError(SourceLoc{what, 0}, treeProblem(problem));
}

namespace {

// NCOMP=, WAVELENGTH_SPLITS= and BANDS= of a spectral map set's file (photon_map.h
// MapBands); none of them: an RGB map.
std::optional<MapBands> bandsFromHeader(const Header& h, const SourceLoc& loc) {
    const std::string ncomp = h.value("NCOMP"), splits = h.value("WAVELENGTH_SPLITS"),
                      bands = h.value("BANDS");
    if (ncomp.empty() && splits.empty() && bands.empty()) return std::nullopt;
    MapBands b;
    int last = 0;
    std::istringstream in(ncomp + " " + splits + " " + bands);
    if (!(in >> b.sampling.n >> b.sampling.wl[0] >> b.sampling.wl[1] >> b.sampling.wl[2] >>
          b.sampling.wl[3] >> b.first >> last) ||
        b.sampling.n <= 3 || b.sampling.n > spectral::kMaxSamples || b.first < 0 ||
        b.first % 3 != 0 || b.first >= b.sampling.n ||
        last != std::min(b.first + 2, b.sampling.n - 1))
        throw InputError(loc,
                         "bad NCOMP, WAVELENGTH_SPLITS or BANDS line in a spectral photon map");
    // The RGB indices are the sampling's own (spectrum.h makeSampling).
    auto chosen = spectral::makeSampling(b.sampling.n, b.sampling.wl[0], b.sampling.wl[3]);
    if (!chosen) throw InputError(loc, "unsupported spectral sampling in a spectral photon map");
    b.sampling.rgb = chosen->sampling.rgb;
    return b;
}

}  // namespace

std::optional<MapBands> mapBandsOf(const spectral::Pass& pass) {
    if (pass.sampling.isRgb()) return std::nullopt;
    return MapBands{pass.sampling, pass.first};
}

void checkMapBands(const std::optional<MapBands>& bands, const spectral::Pass& pass,
                   const std::string& file) {
    const std::optional<MapBands> want = mapBandsOf(pass);
    if (bands == want) return;
    if (!bands)
        throw InputError(file +
                         ": an RGB photon map; render with -cs 3, or make the map with -cs " +
                         std::to_string(pass.sampling.n));
    const spectral::Sampling& s = bands->sampling;
    if (!want)
        throw InputError(
            fmt::format("{}: a spectral photon map (NCOMP={}); render with -cs {} -cw "
                        "{:g} {:g}",
                        file, s.n, s.n, s.wl[3], s.wl[0]));
    throw InputError(
        fmt::format("{}: photon map of bands {} of -cs {} -cw {:g} {:g}, not of the "
                    "rendering's -cs {} -cw {:g} {:g}",
                    file, bands->first, s.n, s.wl[3], s.wl[0], pass.sampling.n, pass.sampling.wl[3],
                    pass.sampling.wl[0]));
}

PhotonMap PhotonMap::readPrologue(std::istream& in, const std::string& what) {
    const SourceLoc loc{what, 0};
    const Header h = readHeader(in, what);
    PhotonMap map;
    map.type_ = typeFromFormat(h.format(), loc);
    const std::string headerVersion = h.value("VERSION");
    // RADIANCE itself only checks the binary version below; the header line lets us give
    // the clearer message before reading binary data.
    if (!headerVersion.empty() && !knownVersion(headerVersion))
        throw InputError(loc, versionProblem(headerVersion));
    if (const std::string block = h.value(kChecksumKey); !block.empty()) {
        char* end = nullptr;
        const unsigned long b = std::strtoul(block.c_str(), &end, 10);
        if (*end != '\0' || b == 0 || b > (1u << 30))
            throw InputError(loc, fmt::format("bad {} line in the header", kChecksumKey));
        map.checksumBlock_ = static_cast<uint32_t>(b);
    }

    map.bands_ = bandsFromHeader(h, loc);

    // Size of the binary part, to check the photon count before allocating anything.
    const std::streampos start = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streampos end = in.tellg();
    in.seekg(start);
    if (start < 0 || end < start || !in) throw InputError(loc, "can't determine file size");
    uint64_t remaining = static_cast<uint64_t>(end - start);

    std::string version;
    for (char c; version.size() <= kMaxVersionLength && in.get(c) && c != '\0';) version += c;
    if (!in || version.size() > kMaxVersionLength)
        throw InputError(loc, "truncated or corrupt photon map (no binary version string)");
    remaining -= version.size() + 1;
    if (!knownVersion(version)) throw InputError(loc, versionProblem(version));
    const bool withRays = version == kPhotonMapFileVersionPD;
    const size_t recordSize = withRays ? kPrimaryRayRecordSize : kPrimaryRecordSize;

    unsigned char fixed[kFixedBinarySize];
    if (remaining < kFixedBinarySize || !readBytes(in, fixed, kFixedBinarySize))
        throw InputError(loc, "truncated photon map (binary header incomplete)");
    remaining -= kFixedBinarySize;
    ByteReader r(fixed, kFixedBinarySize);
    const int64_t numPhotons = r.getInt(8);
    PhotonMapStats& s = map.stats_;
    for (int a = 0; a < 3; ++a) s.avgFlux[a] = static_cast<float>(r.getFlt());
    for (int a = 0; a < 3; ++a) {
        s.bboxMin[a] = static_cast<float>(r.getFlt());
        s.bboxMax[a] = static_cast<float>(r.getFlt());
    }
    for (int a = 0; a < 3; ++a) s.cog[a] = r.getFlt();
    s.cogDist2 = static_cast<float>(r.getFlt());
    // numPrimary is RADIANCE's uint32 PhotonPrimaryIdx; getint sign-extends, we do not.
    const uint64_t numPrimary = static_cast<uint32_t>(r.getInt(4));
    RP_CHECK(r.ok());
    if (numPhotons < 0)
        throw InputError(loc, fmt::format("corrupt photon map (photon count {})", numPhotons));
    s.numPhotons = static_cast<uint64_t>(numPhotons);

    const uint64_t primaryBytes = numPrimary * recordSize;
    // The checksums after the records (record_checksums.h), when the header announces them.
    const uint64_t trailer =
        map.checksumBlock_
            ? 4 * checksumBlocks(static_cast<uint64_t>(std::max<int64_t>(numPhotons, 0)),
                                 map.checksumBlock_)
            : 0;
    if (trailer > remaining) throw InputError(loc, "truncated photon map (checksums incomplete)");
    remaining -= trailer;
    const bool sizeOk = primaryBytes <= remaining &&
                        s.numPhotons == (remaining - primaryBytes) / kPhotonRecordSize &&
                        (remaining - primaryBytes) % kPhotonRecordSize == 0;
    if (!sizeOk)
        throw InputError(
            loc,
            fmt::format("photon map size mismatch: {} photons and {} primaries "
                        "need {} bytes of data but the file holds {} "
                        "(truncated or corrupt file?)",
                        s.numPhotons, numPrimary,
                        s.numPhotons <= remaining
                            ? fmt::format("{}", primaryBytes + s.numPhotons * kPhotonRecordSize)
                            : std::string("more"),
                        remaining));
    if (s.numPhotons > kMaxTreePhotons)
        throw InputError(loc, fmt::format("too many photons ({})", s.numPhotons));
    if (numPrimary && map.type_ != PhotonMapType::Contrib)
        throw InputError(loc, "primary rays in a photon map that is not a contribution map");

    std::vector<unsigned char> buf(std::max<size_t>(primaryBytes, 1));
    if (!readBytes(in, buf.data(), primaryBytes))
        throw InputError(loc, "truncated photon map (primary rays incomplete)");
    map.primaries_.resize(numPrimary);
    if (withRays) map.primaryRays_.resize(numPrimary);
    for (size_t i = 0; i < numPrimary; ++i) {
        ByteReader p(&buf[i * recordSize], recordSize);
        map.primaries_[i].srcIdx = static_cast<int16_t>(p.getInt(2));
        if (!withRays) continue;
        PrimaryRay& ray = map.primaryRays_[i];
        ray.dir = static_cast<int32_t>(p.getInt(4));
        for (size_t a = 0; a < 3; ++a) ray.pos[a] = static_cast<float>(p.getFlt());
        if (!std::isfinite(ray.pos[0]) || !std::isfinite(ray.pos[1]) || !std::isfinite(ray.pos[2]))
            throw InputError(loc, fmt::format("corrupt photon map (primary ray {})", i));
    }
    return map;
}

PhotonMap PhotonMap::read(std::istream& in, const std::string& what, TreeOrder order) {
    PhotonMap map = readPrologue(in, what);
    map.readPhotons(in, what, order);
    return map;
}

void PhotonMap::readPhotons(std::istream& in, const std::string& what, TreeOrder order) {
    const SourceLoc loc{what, 0};
    const PhotonMapStats& s = stats_;
    const uint64_t numPrimary = primaries_.size();
    // Read in chunks (bounded memory for any map size) and decode each chunk in parallel:
    // records are fixed-size, so photon i is at byte 27 i of its chunk. The photon array is
    // on huge pages (BulkVector: 4 KiB page faults cost more than the decoding here).
    photons_.resize(s.numPhotons);
    // With checksums, each block's is computed as it is read: a chunk is whole blocks
    // (one block when a block is larger than a chunk).
    const uint64_t block = checksumBlock_;
    const size_t step =
        block ? std::max<size_t>(block, kReadChunkPhotons / block * block) : kReadChunkPhotons;
    BulkVector<unsigned char> raw(std::max<size_t>(std::min<size_t>(step, s.numPhotons), 1) *
                                  kPhotonRecordSize);
    std::vector<uint32_t> computed;
    for (size_t i = 0; i < s.numPhotons; i += step) {
        const size_t n = std::min<size_t>(step, s.numPhotons - i);
        if (!readBytes(in, raw.data(), n * kPhotonRecordSize))
            throw InputError(loc, fmt::format("truncated photon map (read error at photon {})", i));
        for (size_t b = 0; block && b < n; b += block)
            computed.push_back(recordsChecksum(raw.data() + b * kPhotonRecordSize,
                                               std::min<size_t>(block, n - b) * kPhotonRecordSize));
        decodePhotons(raw.data(), n, photons_.data() + i);
    }
    if (block) checkChecksums(in, what, computed);

    if (const std::string problem = checkPhotonRecords(photons_); !problem.empty())
        throw InputError(loc, treeProblem(problem));
    if (order == TreeOrder::Checked) checkTreeOrder(what);
    if (numPrimary)
        for (const Photon& p : photons_)
            if (p.primary >= numPrimary)
                throw InputError(loc, fmt::format("photon refers to primary ray {} of {}",
                                                  p.primary, numPrimary));
}

void PhotonMap::checkChecksums(std::istream& in, const std::string& what,
                               const std::vector<uint32_t>& computed) const {
    RecordChecksums stored;
    stored.block = checksumBlock_;
    std::vector<unsigned char> bytes(4 * computed.size());
    if (!readBytes(in, bytes.data(), bytes.size()))
        throw InputError(SourceLoc{what, 0}, "truncated photon map (checksums incomplete)");
    stored.decode(bytes.data(), computed.size());
    for (size_t b = 0; b < computed.size(); ++b)
        stored.check(what, b, computed[b], stats_.numPhotons);
}

PhotonMap PhotonMap::load(const std::string& path, TreeOrder order) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(SourceLoc{path, 0},
                         fmt::format("can't open photon map file: {}", std::strerror(errno)));
    PhotonMap map = readPrologue(in, path);
    map.readPhotons(in, path, order);
    return map;
}

}  // namespace rp::pmap
