// RADIANCE compiled mesh reader (see mesh_file.h). The file, as common/readmesh.c reads
// it, after the header:
//   magic (2 bytes): 319 (mesh.h MESHMAGIC) + the writer's object size
//   cube: origin x, y, z and side as NUL-terminated decimal strings
//   (u, v) limits: umin, umax, vmin, vmax as portable reals
//   the octree of triangle IDs (skipped here, structure checked)
//   the materials: binary object records (radiance_objects.h)
//   patch count (4 bytes), then per patch:
//     flags (1 byte): MT_V (1), and MT_N (2) and MT_UV (4) if the patch stores them
//     vertex count (2 bytes, 1..256); x, y, z per vertex (4 bytes each: the position in
//     the cube in units of side/2^32); a 4-byte direction code per vertex (MT_N, 0 = no
//     normal); u, v per vertex (MT_UV, 4 bytes each in units of the limits' span/2^32,
//     u == 0 meaning none)
//     local triangle count (2 bytes, 0..512), 3 one-byte local vertex indices each
//     material count (2 bytes): if above 1, a 2-byte material per local triangle;
//     otherwise one 2-byte material for all of them
//     single joiners (2 bytes, 0..256): a 4-byte vertex ID, two 1-byte local vertices,
//     a 2-byte material each
//     double joiners (2 bytes, 0..256): two 4-byte vertex IDs, one 1-byte local vertex,
//     a 2-byte material each
// A vertex ID is the patch index << 8 | the vertex in that patch. A material is an
// index into the mesh's own materials, -1 for void.
//
// MeshData order: vertices patch by patch (global index = the vertices of all earlier
// patches + local index); triangles patch by patch and, within a patch, its local
// triangles, then its single joiners, then its double joiners, each in file order, with
// vertices in RADIANCE's order (joiners: the non-local vertices first). So RADIANCE's
// triangle ID (patch << 10 | 0x200 * joiner | 0x100 * double | index) maps to one
// MeshData triangle. Void (-1) is accepted as a material wherever it appears and
// becomes kVoid; RADIANCE's checkmesh() refuses it in a mesh that has materials.
#include "scene/mesh_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "scene/portable_reader.h"
#include "scene/radiance_objects.h"
#include "scene/scene_file.h"
#include "util/dir_code.h"

namespace rp {

namespace {
constexpr int kMeshMagic = 1 * 8 + 311;  // mesh.h MESHMAGIC with MAXOBJSIZ 8
constexpr int kFlagV = 1, kFlagN = 2, kFlagUV = 4;
constexpr double kTiny = 1e-6;  // RADIANCE's FTINY
// Smallest possible patch: flags, one vertex, all counts zero and a sole material.
constexpr size_t kMinPatchBytes = 1 + 2 + 12 + 2 + 2 + 2 + 2 + 2;

// Vertex normals are RADIANCE direction codes (util/dir_code.h).
std::array<float, 3> decodeNormal(uint32_t code) {
    const std::array<double, 3> d = decodeDirection(int32_t(code));
    return {static_cast<float>(d[0]), static_cast<float>(d[1]), static_cast<float>(d[2])};
}

struct PatchInfo {
    uint32_t base = 0;  // global index of its first vertex
    uint32_t count = 0;
};
}  // namespace

namespace {

// The patches of a mesh file decoded into a MeshData, one at a time. Triangles hold
// vertex IDs (patch << 8 | local vertex) until finish(), since joiners may point ahead;
// per-vertex normals, (u, v) and flags, and per-triangle materials, are kept only once
// some patch has them.
class PatchDecoder {
public:
    PatchDecoder(PortableReader& r, MeshData& m, size_t npatches)
        : r_(r),
          m_(m),
          patches_(npatches),
          nmats_(int64_t(m.materials.prims.size())),
          uvBounded_(m.uvLimits[1][0] - m.uvLimits[0][0] > kTiny &&
                     m.uvLimits[1][1] - m.uvLimits[0][1] > kTiny) {
        // Room for as many vertices and triangles as the patches and the bytes left can
        // hold (a vertex takes at least 12 bytes, a triangle 3): reserved, not touched,
        // so it costs no memory, and nothing is copied as the arrays grow.
        const size_t maxVerts = std::min(256 * npatches, r.left() / 12);
        const size_t maxTris = std::min(1024 * npatches, r.left() / 3);
        m.positions.reserve(3 * maxVerts + 1);
        flags_.reserve(maxVerts);
        normals_.reserve(maxVerts);
        uvs_.reserve(maxVerts);
        m.triangles.reserve(3 * maxTris);
        mats_.reserve(maxTris);
    }

    void patch(size_t pn) {
        name_ = "patch " + std::to_string(pn);
        r_.setContext(&name_);
        int fl = r_.byte("the flags");
        if (!(fl & kFlagV) || (fl & ~(kFlagV | kFlagN | kFlagUV)))
            r_.fail("flags " + std::to_string(fl) + " of " + name_);
        int64_t nverts = r_.integer(2, "the vertex count");
        if (nverts <= 0 || nverts > 256) r_.fail(std::to_string(nverts) + " vertices in " + name_);
        if ((fl & kFlagUV) && !uvBounded_) r_.fail(name_ + " has (u, v) but the limits are empty");
        patches_[pn] = {nextBase_, static_cast<uint32_t>(nverts)};
        nextBase_ += static_cast<uint32_t>(nverts);
        vertices(patches_[pn].base, fl, nverts);
        triangles(pn, nverts);
        r_.setContext(nullptr);
    }

    void finish() {
        std::vector<uint32_t>& ids = m_.triangles;
        for (size_t i = 0; i < ids.size(); ++i) {
            uint32_t pn = ids[i] >> 8, v = ids[i] & 0xff;
            if (pn >= patches_.size() || v >= patches_[pn].count)
                r_.fail("triangle " + std::to_string(i / 3) + " refers to vertex " +
                        std::to_string(v) + " of patch " + std::to_string(pn) +
                        ", which does not exist");
            ids[i] = patches_[pn].base + v;
        }
        m_.positions.push_back(0.0f);  // the pad that Embree's 16-byte loads read
        const size_t nv = m_.vertexCount();
        if (anyNormal_) {
            normals_.resize(nv, {0, 0, 0});
            m_.normals = std::move(normals_);
        }
        if (anyUV_) {
            uvs_.resize(nv, {0, 0});
            m_.uvs = std::move(uvs_);
        }
        if (anyNormal_ || anyUV_) {
            flags_.resize(nv, 0);
            m_.vertexFlags = std::move(flags_);
        }
        if (mats_.empty())
            m_.soleMaterial = sole_;
        else
            m_.triangleMaterial = std::move(mats_);
    }

private:
    void vertices(size_t first, int fl, int64_t nverts) {
        const double unit = m_.cubeSize / 4294967296.0;
        for (int64_t i = 0; i < nverts; ++i)
            for (int j = 0; j < 3; ++j) {
                uint32_t q = r_.u32("the vertices");
                m_.positions.push_back(static_cast<float>(m_.cubeOrigin[j] + (q + 0.5) * unit));
            }
        if (fl & (kFlagN | kFlagUV)) flags_.resize(first + nverts, 0);
        if (fl & kFlagN) {
            normals_.resize(first + nverts, {0, 0, 0});
            for (int64_t i = 0; i < nverts; ++i) {
                uint32_t code = r_.u32("the normals");
                if (code == 0) continue;
                normals_[first + i] = decodeNormal(code);
                flags_[first + i] |= MeshData::kHasNormal;
                anyNormal_ = true;
            }
        }
        if (fl & kFlagUV) {
            uvs_.resize(first + nverts, {0, 0});
            for (int64_t i = 0; i < nverts; ++i) {
                uint32_t q[2];
                for (auto& c : q) c = r_.u32("the (u, v)");
                if (q[0] == 0) continue;  // mesh.c getmeshvert: only u is tested
                for (int j = 0; j < 2; ++j)
                    uvs_[first + i][j] = static_cast<float>(
                        m_.uvLimits[0][j] +
                        (m_.uvLimits[1][j] - m_.uvLimits[0][j]) * (q[j] + 0.5) / 4294967296.0);
                flags_[first + i] |= MeshData::kHasUV;
                anyUV_ = true;
            }
        }
    }

    void triangles(size_t pn, int64_t nverts) {
        std::vector<uint32_t>& ids = m_.triangles;
        int64_t ntris = r_.integer(2, "the triangle count");
        if (ntris < 0 || ntris > 512)
            r_.fail(std::to_string(ntris) + " local triangles in " + name_);
        for (int64_t t = 0; t < ntris; ++t)
            for (int k = 0; k < 3; ++k) ids.push_back(local(pn, nverts, "the local triangles"));
        if (r_.integer(2, "the material count") > 1) {
            for (int64_t t = 0; t < ntris; ++t) addMaterial(material("the triangle materials"));
        } else {
            const int32_t patchMaterial = material("the sole material");
            for (int64_t t = 0; t < ntris; ++t) addMaterial(patchMaterial);
        }
        int64_t nj1 = r_.integer(2, "the joiner count");
        if (nj1 < 0 || nj1 > 256) r_.fail(std::to_string(nj1) + " joiner triangles in " + name_);
        for (int64_t t = 0; t < nj1; ++t) {
            ids.push_back(joined("the joiner triangles"));
            ids.push_back(local(pn, nverts, "the joiner triangles"));
            ids.push_back(local(pn, nverts, "the joiner triangles"));
            addMaterial(material("the joiner triangles"));
        }
        int64_t nj2 = r_.integer(2, "the double joiner count");
        if (nj2 < 0 || nj2 > 256)
            r_.fail(std::to_string(nj2) + " double joiner triangles in " + name_);
        for (int64_t t = 0; t < nj2; ++t) {
            ids.push_back(joined("the double joiner triangles"));
            ids.push_back(joined("the double joiner triangles"));
            ids.push_back(local(pn, nverts, "the double joiner triangles"));
            addMaterial(material("the double joiner triangles"));
        }
    }

    int32_t material(const char* field) {
        int64_t mat = r_.integer(2, field);
        if (mat != kVoid && (mat < 0 || mat >= nmats_))
            r_.fail("material " + std::to_string(mat) + " of a triangle in " + name_ +
                    " out of range (" + std::to_string(nmats_) + " materials)");
        return static_cast<int32_t>(mat);
    }
    uint32_t local(size_t pn, int64_t nverts, const char* field) {
        int v = r_.byte(field);
        if (v >= nverts)
            r_.fail("vertex " + std::to_string(v) + " of a triangle in " + name_ +
                    " out of range (" + std::to_string(nverts) + " vertices)");
        return (static_cast<uint32_t>(pn) << 8) | static_cast<uint32_t>(v);
    }
    uint32_t joined(const char* field) {
        int64_t id = r_.integer(4, field);
        if (id < 0) r_.fail("joiner vertex ID " + std::to_string(id) + " in " + name_);
        return static_cast<uint32_t>(id);
    }
    // Materials per triangle only once two differ (most meshes have one).
    void addMaterial(int32_t mat) {
        if (materialCount_ == 0) sole_ = mat;
        if (mats_.empty() && mat != sole_) mats_.assign(materialCount_, sole_);
        if (!mats_.empty()) mats_.push_back(mat);
        ++materialCount_;
    }

    PortableReader& r_;
    MeshData& m_;
    std::vector<PatchInfo> patches_;
    const int64_t nmats_;
    const bool uvBounded_;
    std::vector<int32_t> mats_;
    std::vector<std::array<float, 3>> normals_;
    std::vector<std::array<float, 2>> uvs_;
    std::vector<uint8_t> flags_;
    bool anyNormal_ = false, anyUV_ = false;
    uint32_t nextBase_ = 0;
    size_t materialCount_ = 0;
    int32_t sole_ = kVoid;
    std::string name_;  // "patch N", the reader's context for messages
};

}  // namespace

MeshData decodeMeshFile(std::string_view bytes, const std::string& what,
                        const std::function<void(size_t)>& consumed) {
    const SourceLoc loc{what, 0};
    Header header;
    std::string_view rest;
    if (!splitHeader(bytes, header, rest))
        throw InputError(loc, "not a RADIANCE mesh file (no RADIANCE header)");
    if (header.format() != kRadianceMeshFormat)
        throw InputError(loc, "not a RADIANCE mesh file (FORMAT=" + header.format() + ")");

    size_t pos = 0;
    const size_t offset = size_t(rest.data() - bytes.data());  // of rest in bytes
    PortableReader r(rest, pos, what, "mesh file");
    int64_t objsize = r.integer(2, "the magic number") - kMeshMagic;
    if (objsize <= 0 || objsize > 8)
        throw InputError(loc, "incompatible mesh file format (bad magic number)");

    MeshData m;
    m.path = what;
    readRadianceCube(r, m.cubeOrigin, m.cubeSize);
    if (!(m.cubeSize > kTiny)) r.fail("cube size " + std::to_string(m.cubeSize));
    for (int i = 0; i < 2; ++i) {
        m.uvLimits[0][i] = r.real("the (u, v) limits");
        m.uvLimits[1][i] = r.real("the (u, v) limits");
    }
    // Octree leaves hold triangle IDs, non-negative OBJECTs.
    skipRadianceTree(r, static_cast<int>(objsize), int64_t{1} << 31);
    if (consumed) consumed(offset + r.pos());
    m.materials = decodeRadianceObjects(rest, pos, static_cast<int>(objsize), what);
    for (const auto& p : m.materials.prims)
        if (isSurface(p.type))
            r.fail("surface " + std::string(primTypeName(p.type)) + " '" + p.name +
                   "' among the mesh's materials");

    size_t npatches = r.count(4, kMinPatchBytes, "patch count");
    if (npatches > (size_t{1} << 22)) r.fail(std::to_string(npatches) + " patches");  // 22-bit IDs
    PatchDecoder patches(r, m, npatches);
    for (size_t pn = 0; pn < npatches; ++pn) {
        if (pn % 1024 == 0 && consumed) consumed(offset + r.pos());
        patches.patch(pn);
    }
    if (r.left() != 0) r.fail(std::to_string(r.left()) + " unexpected bytes after the last patch");
    patches.finish();
    return m;
}

MeshData readMeshFile(const std::string& path) {
    // Mapped rather than read: the octree that RADIANCE stores first (most of the file)
    // and the patches already decoded are handed back as decoding goes on, so a mesh
    // file of hundreds of megabytes never sits in memory beside its mesh.
    const SourceLoc loc{path, 0};
    int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0)
        throw InputError(loc, std::string("cannot open mesh file (") + std::strerror(errno) + ")");
    struct stat st;
    if (::fstat(fd, &st) != 0 || st.st_size <= 0) {
        ::close(fd);
        throw InputError(loc, st.st_size == 0 ? "empty mesh file" : "cannot read mesh file");
    }
    const size_t size = size_t(st.st_size);
    void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    ::close(fd);
    if (map == MAP_FAILED)
        throw InputError(loc, std::string("cannot read mesh file (") + std::strerror(errno) + ")");
    ::madvise(map, size, MADV_SEQUENTIAL);
    const size_t page = size_t(::sysconf(_SC_PAGESIZE));
    size_t released = 0;
    auto consumed = [&](size_t upTo) {
        size_t end = upTo / page * page;
        if (end > released) {
            ::madvise(static_cast<char*>(map) + released, end - released, MADV_DONTNEED);
            released = end;
        }
    };
    try {
        MeshData m =
            decodeMeshFile(std::string_view(static_cast<const char*>(map), size), path, consumed);
        ::munmap(map, size);
        return m;
    } catch (...) {
        ::munmap(map, size);
        throw;
    }
}

}  // namespace rp
