// Frozen scene file encoding/decoding and RADIANCE octree file lists (see scene_file.h).
//
// Payload layout, all integers little-endian, doubles as IEEE-754 bits:
//   "RPSCENE\0"  u32 version  u64 size (bytes after this field)
//   u32 nLocFiles, each str          -- SourceLoc file names, referenced by index
//   u32 nInputs,   each str path, i64 mtime
//   u32 nPrims,    each str type, str name, str modifierName, i32 modifier,
//                  u32 locFile, i32 locLine, u32 nS + str[], u32 nI + i64[], u32 nR + f64[]
//   u64 FNV-1a hash of everything between the size field and the hash
// where str = u32 length + bytes. Types are stored by RADIANCE name so that the file
// does not depend on the order of PrimType.
#include "scene/scene_file.h"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "scene/portable_reader.h"
#include "scene/radiance_objects.h"
#include "util/file_write.h"

namespace rp {

namespace {
constexpr char kMagic[8] = {'R', 'P', 'S', 'C', 'E', 'N', 'E', '\0'};

uint64_t fnv1a(std::string_view s) {
    uint64_t h = 14695981039346656037ull;
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    return h;
}

class Encoder {
public:
    void u32(uint32_t v) { put(v, 4); }
    void i32(int32_t v) { put(static_cast<uint32_t>(v), 4); }
    void u64(uint64_t v) { put(v, 8); }
    void i64(int64_t v) { put(static_cast<uint64_t>(v), 8); }
    void f64(double v) {
        uint64_t bits;
        std::memcpy(&bits, &v, 8);
        put(bits, 8);
    }
    void str(const std::string& s) {
        u32(static_cast<uint32_t>(s.size()));
        out.append(s);
    }
    std::string out;

private:
    void put(uint64_t v, int bytes) {
        for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
    }
};

class Decoder {
public:
    Decoder(std::string_view in, const std::string& what) : in_(in), what_(what) {}

    [[noreturn]] void fail(const std::string& why) const {
        throw InputError(SourceLoc{what_, 0}, "corrupted or truncated scene file (" + why + ")");
    }
    void need(size_t n, const char* field) const {
        if (in_.size() - pos_ < n) fail(std::string("ends inside ") + field);
    }
    uint32_t u32(const char* f) { return static_cast<uint32_t>(get(4, f)); }
    int32_t i32(const char* f) { return static_cast<int32_t>(u32(f)); }
    uint64_t u64(const char* f) { return get(8, f); }
    int64_t i64(const char* f) { return static_cast<int64_t>(get(8, f)); }
    double f64(const char* f) {
        uint64_t bits = get(8, f);
        double v;
        std::memcpy(&v, &bits, 8);
        return v;
    }
    std::string str(const char* f) {
        uint32_t n = u32(f);
        need(n, f);
        std::string s(in_.substr(pos_, n));
        pos_ += n;
        return s;
    }
    // A count of elements at least `minBytes` each: bounded by what is left, so a
    // corrupted count cannot make us allocate gigabytes.
    uint32_t count(const char* f, size_t minBytes) {
        uint32_t n = u32(f);
        if (static_cast<uint64_t>(n) * minBytes > in_.size() - pos_)
            fail(std::string("impossible ") + f + " count " + std::to_string(n));
        return n;
    }
    size_t pos() const { return pos_; }
    std::string_view view(size_t from, size_t to) const { return in_.substr(from, to - from); }
    bool atEnd() const { return pos_ == in_.size(); }

private:
    uint64_t get(int bytes, const char* f) {
        need(bytes, f);
        uint64_t v = 0;
        for (int i = 0; i < bytes; ++i)
            v |= static_cast<uint64_t>(static_cast<unsigned char>(in_[pos_ + i])) << (8 * i);
        pos_ += bytes;
        return v;
    }
    std::string_view in_;
    size_t pos_ = 0;
    std::string what_;
};
}  // namespace

std::string encodeScene(const Scene& scene) {
    std::vector<std::string> files;
    std::unordered_map<std::string, uint32_t> fileIndex;
    for (const auto& p : scene.prims)
        if (fileIndex.emplace(p.loc.file, static_cast<uint32_t>(files.size())).second)
            files.push_back(p.loc.file);

    Encoder body;
    body.u32(static_cast<uint32_t>(files.size()));
    for (const auto& f : files) body.str(f);
    body.u32(static_cast<uint32_t>(scene.inputs.size()));
    for (const auto& in : scene.inputs) {
        body.str(in.path);
        body.i64(in.mtime);
    }
    body.u32(static_cast<uint32_t>(scene.prims.size()));
    for (const auto& p : scene.prims) {
        body.str(std::string(primTypeName(p.type)));
        body.str(p.name);
        body.str(p.modifierName);
        body.i32(p.modifier);
        body.u32(fileIndex.at(p.loc.file));
        body.i32(p.loc.line);
        body.u32(static_cast<uint32_t>(p.sargs.size()));
        for (const auto& s : p.sargs) body.str(s);
        body.u32(static_cast<uint32_t>(p.iargs.size()));
        for (long v : p.iargs) body.i64(v);
        body.u32(static_cast<uint32_t>(p.rargs.size()));
        for (double v : p.rargs) body.f64(v);
    }
    body.u64(fnv1a(body.out));

    Encoder head;
    head.out.assign(kMagic, sizeof kMagic);
    head.u32(kSceneFileVersion);
    head.u64(body.out.size());
    return head.out + body.out;
}

Scene decodeScene(std::string_view payload, const std::string& what) {
    Decoder d(payload, what);
    d.need(sizeof kMagic, "magic");
    if (payload.substr(0, sizeof kMagic) != std::string_view(kMagic, sizeof kMagic))
        d.fail("bad magic number");
    Decoder after(payload.substr(sizeof kMagic), what);
    uint32_t version = after.u32("version");
    if (version != kSceneFileVersion)
        throw InputError(SourceLoc{what, 0}, "scene file version " + std::to_string(version) +
                                                 " is not supported (expected " +
                                                 std::to_string(kSceneFileVersion) +
                                                 "); run oconv again");
    uint64_t size = after.u64("size");
    std::string_view body = payload.substr(sizeof kMagic + 12);
    if (body.size() != size)
        d.fail("size " + std::to_string(body.size()) + " bytes, header says " +
               std::to_string(size));
    if (size < 8) d.fail("no checksum");
    uint64_t stored = 0;
    for (int i = 0; i < 8; ++i)
        stored |= static_cast<uint64_t>(static_cast<unsigned char>(body[size - 8 + i])) << (8 * i);
    if (fnv1a(body.substr(0, size - 8)) != stored) d.fail("checksum mismatch");

    Decoder b(body.substr(0, size - 8), what);
    Scene scene;
    std::vector<std::string> files(b.count("location file", 4));
    for (auto& f : files) f = b.str("location file name");
    scene.inputs.resize(b.count("input", 12));
    for (auto& in : scene.inputs) {
        in.path = b.str("input path");
        in.mtime = b.i64("input mtime");
    }
    scene.prims.resize(b.count("primitive", 40));
    for (size_t i = 0; i < scene.prims.size(); ++i) {
        Primitive& p = scene.prims[i];
        std::string type = b.str("type");
        if (!primTypeFromName(type, p.type) || p.type == PrimType::Alias)
            b.fail("unknown type '" + type + "' in record " + std::to_string(i));
        p.name = b.str("name");
        p.modifierName = b.str("modifier name");
        p.modifier = b.i32("modifier");
        // A modifier is always defined before its use, and is never a surface.
        if (p.modifier < kVoid || p.modifier >= static_cast<int32_t>(i) ||
            (p.modifier != kVoid && isSurface(scene.prims[p.modifier].type)))
            b.fail("bad modifier index in record " + std::to_string(i));
        uint32_t file = b.u32("location");
        if (file >= files.size()) b.fail("bad location in record " + std::to_string(i));
        p.loc = SourceLoc{files[file], b.i32("line")};
        p.sargs.resize(b.count("string argument", 4));
        for (auto& s : p.sargs) s = b.str("string argument");
        p.iargs.resize(b.count("integer argument", 8));
        for (auto& v : p.iargs) v = static_cast<long>(b.i64("integer argument"));
        p.rargs.resize(b.count("real argument", 8));
        for (auto& v : p.rargs) v = b.f64("real argument");
    }
    if (!b.atEnd()) b.fail("unexpected bytes after the last record");
    return scene;
}

std::string sceneFileBytes(const Scene& scene, const std::vector<std::string>& headerLines) {
    Header h;
    h.lines = headerLines;
    h.lines.push_back(std::string("FORMAT=") + kSceneFileFormat);
    std::ostringstream out;
    writeHeader(out, h);
    return out.str() + encodeScene(scene);
}

void saveSceneFile(const std::string& path, const Scene& scene,
                   const std::vector<std::string>& headerLines) {
    writeFileAtomically(path, sceneFileBytes(scene, headerLines));
}

bool splitHeader(std::string_view bytes, Header& header, std::string_view& rest) {
    std::string magic = std::string(kHeaderMagic) + "\n";
    if (bytes.substr(0, magic.size()) != magic) return false;
    // The header is text and ends at the first empty line; only that part is copied.
    size_t end = bytes.find("\n\n");
    if (end == std::string_view::npos) return false;
    std::istringstream in(std::string(bytes.substr(0, end + 2)));
    if (!tryReadHeader(in, header)) return false;
    rest = bytes.substr(end + 2);
    return true;
}

namespace {
// octree.h OCTMAGIC and mesh.h MESHMAGIC with MAXOBJSIZ 8: the writers store the magic
// plus sizeof(OBJECT) as a 2-byte big-endian integer (portio.c putint).
constexpr int kOctMagic = 4 * 8 + 251;
constexpr int kMeshMagic = 1 * 8 + 311;

// Reads the magic number and returns the object size it gives.
int readMagic(PortableReader& r, bool mesh, const std::string& what) {
    int64_t objSize = r.integer(2, "the magic number") - (mesh ? kMeshMagic : kOctMagic);
    if (objSize <= 0 || objSize > 8)
        throw InputError(SourceLoc{what, 0},
                         mesh ? "incompatible mesh file format" : "incompatible octree format");
    return static_cast<int>(objSize);
}

struct OctreeStart {
    int objSize = 0;
    RadianceCube cube;
    std::vector<std::string> files;
};

OctreeStart readOctreeStart(PortableReader& r, const std::string& what) {
    OctreeStart s;
    s.objSize = readMagic(r, false, what);
    s.cube.text = readRadianceCube(r, s.cube.origin, s.cube.size);
    for (std::string name = r.str("the scene file names"); !name.empty();
         name = r.str("the scene file names"))
        s.files.push_back(std::move(name));
    return s;
}
}  // namespace

std::vector<std::string> radianceOctreeFiles(std::string_view bin, const std::string& what) {
    size_t pos = 0;
    PortableReader r(bin, pos, what, "octree");
    return readOctreeStart(r, what).files;
}

Scene decodeRadianceFrozenOctree(std::string_view bin, const std::string& what) {
    size_t pos = 0;
    PortableReader r(bin, pos, what, "octree");
    OctreeStart start = readOctreeStart(r, what);
    if (!start.files.empty()) r.fail("not a frozen octree: it names scene files");
    // Each object takes at least 1 + objsize + 1 + 2 + 2 bytes.
    auto count = static_cast<int64_t>(r.count(start.objSize, 6 + start.objSize, "object count"));
    skipRadianceTree(r, start.objSize, count);
    Scene scene = decodeRadianceObjects(bin, pos, start.objSize, what);
    if (static_cast<int64_t>(scene.prims.size()) != count)
        r.fail(std::to_string(scene.prims.size()) + " objects, the octree says " +
               std::to_string(count));
    if (r.left() != 0) r.fail(std::to_string(r.left()) + " unexpected bytes after the objects");
    return scene;
}

RadianceCube radianceCube(std::string_view bin, bool mesh, const std::string& what) {
    size_t pos = 0;
    PortableReader r(bin, pos, what, mesh ? "mesh file" : "octree");
    readMagic(r, mesh, what);
    RadianceCube cube;
    cube.text = readRadianceCube(r, cube.origin, cube.size);
    return cube;
}

}  // namespace rp
