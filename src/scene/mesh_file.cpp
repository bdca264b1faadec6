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

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "scene/portable_reader.h"
#include "scene/radiance_objects.h"
#include "scene/scene_file.h"

namespace rp {

namespace {
constexpr int kMeshMagic = 1 * 8 + 311;  // mesh.h MESHMAGIC with MAXOBJSIZ 8
constexpr int kFlagV = 1, kFlagN = 2, kFlagUV = 4;
constexpr double kTiny = 1e-6;  // RADIANCE's FTINY
// Smallest possible patch: flags, one vertex, all counts zero and a sole material.
constexpr size_t kMinPatchBytes = 1 + 2 + 12 + 2 + 2 + 2 + 2 + 2;

// dircode.c's 32-bit direction code: sign bits for x, y, z (bits 0-2), two 13-bit
// components (bits 5-17 and 18-30, in units of 1/11584.5) whose axes bits 3 and 4
// choose, and the third component making the vector unit length.
std::array<float, 3> decodeDirection(uint32_t code) {
    constexpr double kScale = 11584.5;
    double a = ((code >> 5) & 0x1fff) / kScale;
    double b = ((code >> 18) & 0x1fff) / kScale;
    double c = std::sqrt(std::max(0.0, 1.0 - a * a - b * b));
    bool firstIsX = code & 8, secondIsZ = code & 16;
    double d[3];
    if (firstIsX) {
        d[0] = a;
        d[1] = secondIsZ ? c : b;
        d[2] = secondIsZ ? b : c;
    } else {
        d[1] = a;
        d[0] = secondIsZ ? c : b;
        d[2] = secondIsZ ? b : c;
    }
    for (int i = 0; i < 3; ++i)
        if (code & (1u << i)) d[i] = -d[i];
    return {static_cast<float>(d[0]), static_cast<float>(d[1]), static_cast<float>(d[2])};
}

struct PatchInfo {
    uint32_t base = 0;  // global index of its first vertex
    uint32_t count = 0;
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
    const bool uvBounded = m.uvLimits[1][0] - m.uvLimits[0][0] > kTiny &&
                           m.uvLimits[1][1] - m.uvLimits[0][1] > kTiny;
    // Octree leaves hold triangle IDs, non-negative OBJECTs.
    skipRadianceTree(r, static_cast<int>(objsize), int64_t{1} << 31);
    if (consumed) consumed(offset + r.pos());
    m.materials = decodeRadianceObjects(rest, pos, static_cast<int>(objsize), what);
    const auto nmats = static_cast<int64_t>(m.materials.prims.size());
    for (const auto& p : m.materials.prims)
        if (isSurface(p.type))
            r.fail("surface " + std::string(primTypeName(p.type)) + " '" + p.name +
                   "' among the mesh's materials");

    size_t npatches = r.count(4, kMinPatchBytes, "patch count");
    if (npatches > (size_t{1} << 22)) r.fail(std::to_string(npatches) + " patches");  // 22-bit IDs
    std::vector<PatchInfo> patches(npatches);
    // Triangles hold vertex IDs until every patch is known (joiners may point ahead).
    std::vector<int32_t> mats;
    std::vector<std::array<float, 3>> normals;
    std::vector<std::array<float, 2>> uvs;
    std::vector<uint8_t> flags;
    bool anyNormal = false, anyUV = false;
    uint32_t nextBase = 0;

    // Room for as many vertices and triangles as the patches and the bytes left can hold
    // (a vertex takes at least 12 bytes, a triangle 3): reserved, not touched, so it
    // costs no memory, and nothing is copied as the arrays grow.
    const size_t maxVerts = std::min(256 * npatches, r.left() / 12);
    const size_t maxTris = std::min(1024 * npatches, r.left() / 3);
    m.positions.reserve(3 * maxVerts + 1);
    flags.reserve(maxVerts);
    normals.reserve(maxVerts);
    uvs.reserve(maxVerts);
    m.triangles.reserve(3 * maxTris);
    mats.reserve(maxTris);
    std::vector<uint32_t>& ids = m.triangles;  // vertex IDs, made indices at the end
    // Materials per triangle only once two differ (most meshes have one).
    size_t materialCount = 0;
    int32_t sole = kVoid;
    auto addMaterial = [&](int32_t mat) {
        if (materialCount == 0) sole = mat;
        if (mats.empty() && mat != sole) mats.assign(materialCount, sole);
        if (!mats.empty()) mats.push_back(mat);
        ++materialCount;
    };
    std::string patch;
    for (size_t pn = 0; pn < npatches; ++pn) {
        if (pn % 1024 == 0 && consumed) consumed(offset + r.pos());
        patch = "patch " + std::to_string(pn);
        r.setContext(&patch);
        auto material = [&](const char* field) {
            int64_t mat = r.integer(2, field);
            if (mat != kVoid && (mat < 0 || mat >= nmats))
                r.fail("material " + std::to_string(mat) + " of a triangle in " + patch +
                       " out of range (" + std::to_string(nmats) + " materials)");
            return static_cast<int32_t>(mat);
        };
        auto local = [&](int64_t nverts, const char* field) {
            int v = r.byte(field);
            if (v >= nverts)
                r.fail("vertex " + std::to_string(v) + " of a triangle in " + patch +
                       " out of range (" + std::to_string(nverts) + " vertices)");
            return (static_cast<uint32_t>(pn) << 8) | static_cast<uint32_t>(v);
        };
        auto joined = [&](const char* field) {
            int64_t id = r.integer(4, field);
            if (id < 0) r.fail("joiner vertex ID " + std::to_string(id) + " in " + patch);
            return static_cast<uint32_t>(id);
        };

        int fl = r.byte("the flags");
        if (!(fl & kFlagV) || (fl & ~(kFlagV | kFlagN | kFlagUV)))
            r.fail("flags " + std::to_string(fl) + " of " + patch);
        int64_t nverts = r.integer(2, "the vertex count");
        if (nverts <= 0 || nverts > 256)
            r.fail(std::to_string(nverts) + " vertices in " + patch);
        if ((fl & kFlagUV) && !uvBounded) r.fail(patch + " has (u, v) but the limits are empty");
        patches[pn] = {nextBase, static_cast<uint32_t>(nverts)};
        nextBase += static_cast<uint32_t>(nverts);

        const double unit = m.cubeSize / 4294967296.0;
        for (int64_t i = 0; i < nverts; ++i)
            for (int j = 0; j < 3; ++j) {
                uint32_t q = r.u32("the vertices");
                m.positions.push_back(static_cast<float>(m.cubeOrigin[j] + (q + 0.5) * unit));
            }
        // Per-vertex arrays only once some patch has normals or (u, v).
        const size_t first = patches[pn].base;
        if (fl & (kFlagN | kFlagUV)) flags.resize(first + nverts, 0);
        if (fl & kFlagN) normals.resize(first + nverts, {0, 0, 0});
        if (fl & kFlagUV) uvs.resize(first + nverts, {0, 0});
        if (fl & kFlagN)
            for (int64_t i = 0; i < nverts; ++i) {
                uint32_t code = r.u32("the normals");
                if (code == 0) continue;
                normals[first + i] = decodeDirection(code);
                flags[first + i] |= MeshData::kHasNormal;
                anyNormal = true;
            }
        if (fl & kFlagUV)
            for (int64_t i = 0; i < nverts; ++i) {
                uint32_t q[2];
                for (auto& c : q) c = r.u32("the (u, v)");
                if (q[0] == 0) continue;  // mesh.c getmeshvert: only u is tested
                for (int j = 0; j < 2; ++j)
                    uvs[first + i][j] = static_cast<float>(
                        m.uvLimits[0][j] +
                        (m.uvLimits[1][j] - m.uvLimits[0][j]) * (q[j] + 0.5) / 4294967296.0);
                flags[first + i] |= MeshData::kHasUV;
                anyUV = true;
            }

        int64_t ntris = r.integer(2, "the triangle count");
        if (ntris < 0 || ntris > 512)
            r.fail(std::to_string(ntris) + " local triangles in " + patch);
        for (int64_t t = 0; t < ntris; ++t)
            for (int k = 0; k < 3; ++k) ids.push_back(local(nverts, "the local triangles"));
        if (r.integer(2, "the material count") > 1) {
            for (int64_t t = 0; t < ntris; ++t) addMaterial(material("the triangle materials"));
        } else {
            int32_t sole = material("the sole material");
            for (int64_t t = 0; t < ntris; ++t) addMaterial(sole);
        }

        int64_t nj1 = r.integer(2, "the joiner count");
        if (nj1 < 0 || nj1 > 256) r.fail(std::to_string(nj1) + " joiner triangles in " + patch);
        for (int64_t t = 0; t < nj1; ++t) {
            ids.push_back(joined("the joiner triangles"));
            ids.push_back(local(nverts, "the joiner triangles"));
            ids.push_back(local(nverts, "the joiner triangles"));
            addMaterial(material("the joiner triangles"));
        }
        int64_t nj2 = r.integer(2, "the double joiner count");
        if (nj2 < 0 || nj2 > 256)
            r.fail(std::to_string(nj2) + " double joiner triangles in " + patch);
        for (int64_t t = 0; t < nj2; ++t) {
            ids.push_back(joined("the double joiner triangles"));
            ids.push_back(joined("the double joiner triangles"));
            ids.push_back(local(nverts, "the double joiner triangles"));
            addMaterial(material("the double joiner triangles"));
        }
    }
    r.setContext(nullptr);
    if (r.left() != 0)
        r.fail(std::to_string(r.left()) + " unexpected bytes after the last patch");

    for (size_t i = 0; i < ids.size(); ++i) {
        uint32_t pn = ids[i] >> 8, v = ids[i] & 0xff;
        if (pn >= npatches || v >= patches[pn].count)
            r.fail("triangle " + std::to_string(i / 3) + " refers to vertex " +
                   std::to_string(v) + " of patch " + std::to_string(pn) + ", which does not exist");
        ids[i] = patches[pn].base + v;
    }
    m.positions.push_back(0.0f);  // the pad that Embree's 16-byte loads read
    const size_t nv = m.vertexCount();
    if (anyNormal) {
        normals.resize(nv, {0, 0, 0});
        m.normals = std::move(normals);
    }
    if (anyUV) {
        uvs.resize(nv, {0, 0});
        m.uvs = std::move(uvs);
    }
    if (anyNormal || anyUV) {
        flags.resize(nv, 0);
        m.vertexFlags = std::move(flags);
    }
    if (mats.empty())
        m.soleMaterial = sole;
    else
        m.triangleMaterial = std::move(mats);
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
        MeshData m = decodeMeshFile(std::string_view(static_cast<const char*>(map), size), path,
                                    consumed);
        ::munmap(map, size);
        return m;
    } catch (...) {
        ::munmap(map, size);
        throw;
    }
}

}  // namespace rp
