// See mesh_write.h: the byte layout of RADIANCE's writemesh() (ot/writemesh.c).
#include "scene/mesh_write.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "scene/mesh_build.h"
#include "scene/octree_nodes.h"
#include "scene/radiance_objects.h"
#include "util/error.h"
#include "util/file_write.h"
#include "util/portable_io.h"

namespace rp {
namespace {

using namespace portable;
using meshbuild::BuiltMesh;
using meshbuild::Node;
using meshbuild::Patch;

constexpr int kObjSize = 4;              // sizeof(OBJECT) in RADIANCE's standard build
constexpr int kMeshMagic = 1 * 8 + 311;  // mesh.h MESHMAGIC (MAXOBJSIZ 8)

void putPatch(std::string& out, const Patch& p) {
    putInt(out, 1 | (p.hasNorm ? 2 : 0) | (p.hasUV ? 4 : 0), 1);
    putInt(out, static_cast<int64_t>(p.xyz.size()), 2);
    for (const auto& v : p.xyz)
        for (uint32_t c : v) putInt(out, c, 4);
    if (p.hasNorm)
        for (int32_t n : p.norm) putInt(out, n, 4);
    if (p.hasUV)
        for (const auto& uv : p.uv)
            for (uint32_t c : uv) putInt(out, c, 4);
    putInt(out, static_cast<int64_t>(p.tri.size()), 2);
    for (const auto& t : p.tri)
        for (uint8_t v : t) putInt(out, v, 1);
    if (p.trimat.empty()) {
        putInt(out, 1, 2);
        putInt(out, p.solemat, 2);
    } else {
        putInt(out, static_cast<int64_t>(p.trimat.size()), 2);
        for (int16_t m : p.trimat) putInt(out, m, 2);
    }
    putInt(out, static_cast<int64_t>(p.j1.size()), 2);
    for (const auto& j : p.j1) {
        putInt(out, j.v1j, 4);
        putInt(out, j.v2, 1);
        putInt(out, j.v3, 1);
        putInt(out, j.mat, 2);
    }
    putInt(out, static_cast<int64_t>(p.j2.size()), 2);
    for (const auto& j : p.j2) {
        putInt(out, j.v1j, 4);
        putInt(out, j.v2j, 4);
        putInt(out, j.v3, 1);
        putInt(out, j.mat, 2);
    }
}

std::string g12(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.12g", x);
    return buf;
}

void tally(const meshbuild::Octree& t, Node n, MeshStats& s) {
    if (n == meshbuild::kEmpty) {
        s.emptyLeaves++;
    } else if (meshbuild::isLeaf(n)) {
        s.fullLeaves++;
        s.leafTriangles += static_cast<long>(t.sets[meshbuild::setIndex(n)].size());
    } else {
        for (int i = 0; i < 8; ++i) tally(t, t.trees[n][i], s);
    }
}

MeshStats statsOf(const BuiltMesh& m) {
    MeshStats s;
    s.materials = m.nmats;
    s.patches = static_cast<int>(m.patches.size());
    tally(m.tree, m.tree.root, s);
    long withNormSlots = 0, withUVSlots = 0;
    for (const Patch& p : m.patches) {
        int nv = static_cast<int>(p.xyz.size());
        s.vertices += nv;
        if (p.hasNorm) {
            for (int32_t n : p.norm) s.withNormal += n != 0;
            withNormSlots += nv;
        }
        if (p.hasUV) {
            for (const auto& uv : p.uv) s.withUV += uv[0] != 0;
            withUVSlots += nv;
        }
        s.localTris += static_cast<int>(p.tri.size());
        s.joinerTris += static_cast<int>(p.j1.size());
        s.doubleJoinerTris += static_cast<int>(p.j2.size());
    }
    // sizeof(MESHPATCH), uint32, int32, PTri, PJoin1, PJoin2 in a 64-bit RADIANCE build.
    s.megabytes = (s.patches * 72.0 + s.vertices * 12.0 + withNormSlots * 4.0 + withUVSlots * 8.0 +
                   s.localTris * 3.0 + s.joinerTris * 8.0 + s.doubleJoinerTris * 12.0) /
                  (1024. * 1024.);
    return s;
}

}  // namespace

std::string formatMeshStats(const MeshStats& s) {
    char buf[1024];
    int tris = s.localTris + s.joinerTris + s.doubleJoinerTris;
    int leaves = s.fullLeaves + s.emptyLeaves;
    std::snprintf(buf, sizeof buf,
                  "Mesh statistics:\n"
                  "\t%ld materials\n"
                  "\t%d patches (%.2f MBytes)\n"
                  "\t%d vertices (%.1f%% w/ normals, %.1f%% w/ uv)\n"
                  "\t%d triangles (%.1f%% local, %.1f%% joiner)\n"
                  "\t%d leaves in octree (%.1f%% empty, %.2f avg. set size)\n",
                  s.materials, s.patches, s.megabytes, s.vertices, 100. * s.withNormal / s.vertices,
                  100. * s.withUV / s.vertices, tris, 100. * s.localTris / tris,
                  100. * s.joinerTris / tris, leaves, 100. * s.emptyLeaves / leaves,
                  static_cast<double>(s.leafTriangles) / s.fullLeaves);
    return buf;
}

std::string encodeMeshFile(const MeshSource& source, const MeshWriteOptions& options,
                           const std::vector<std::string>& headerLines, MeshStats* stats) {
    BuiltMesh m = meshbuild::buildMesh(source, options);
    std::string out = "#?RADIANCE\n";
    for (const std::string& line : headerLines) out += line + "\n";
    out += "FORMAT=Radiance_tmesh\n\n";
    putInt(out, kMeshMagic + kObjSize, 2);
    for (double c : m.cubeOrigin) putStr(out, g12(c));
    putStr(out, g12(m.cubeSize));
    for (int i = 0; i < 2; ++i) {
        putFlt(out, m.uvLimits[0][i]);
        putFlt(out, m.uvLimits[1][i]);
    }
    octree::putOctreeNodes(out, m.tree, kObjSize);
    Scene used;
    used.prims.assign(source.materials.prims.begin(), source.materials.prims.begin() + m.nmats);
    encodeRadianceObjects(used, kObjSize, out);
    putInt(out, static_cast<int64_t>(m.patches.size()), 4);
    for (const Patch& p : m.patches) putPatch(out, p);
    if (stats) *stats = statsOf(m);
    return out;
}

std::string encodeMeshFile(const MeshData& mesh, int objlim, int maxres,
                           const std::vector<std::string>& headerLines) {
    MeshSource src;
    src.materials = mesh.materials;
    src.triangles.reserve(mesh.triangleCount());
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        MeshTriangleInput in;
        in.hasNormals = in.hasUV = true;
        for (int k = 0; k < 3; ++k) {
            uint32_t v = mesh.triangles[3 * t + k];
            for (int j = 0; j < 3; ++j) in.v[k][j] = mesh.positions[3 * v + j];
            uint8_t fl = mesh.flagsOf(v);
            if (fl & MeshData::kHasNormal)
                for (int j = 0; j < 3; ++j) in.n[k][j] = mesh.normals[v][j];
            else
                in.hasNormals = false;
            if (fl & MeshData::kHasUV)
                for (int j = 0; j < 2; ++j) in.uv[k][j] = mesh.uvs[v][j];
            else
                in.hasUV = false;
        }
        in.material = mesh.materialOf(t);
        in.loc = SourceLoc{mesh.path, 0};
        src.triangles.push_back(in);
    }
    MeshWriteOptions opt;
    opt.objlim = objlim;
    opt.maxres = maxres;
    return encodeMeshFile(src, opt, headerLines);
}

void saveMeshFile(const std::string& path, const std::string& bytes) {
    writeFileAtomically(path, bytes);
}

}  // namespace rp
