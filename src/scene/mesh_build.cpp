// See mesh_build.h. Every tolerance and order of evaluation here follows RADIANCE's
// obj2mesh, because the file must come out the same: which triangle meets which
// octree cube, the order the octree is walked in (it decides patch membership), and
// how positions, (u, v) and normals are quantised.
#include "scene/mesh_build.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "scene/radiance_geom.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::meshbuild {
namespace {

using radgeom::cross;
using radgeom::dot;
using radgeom::kHuge;
using radgeom::kTiny;
using radgeom::sub;
using radgeom::Vec;
using UV = std::array<double, 2>;

constexpr double kCosTol = 0.999995;  // tmesh.h COSTOL: normals this close are "flat"
using octree::kMaxSet;
constexpr int kHasN = 2, kHasUV = 4, kHasV = 1;

// A triangle once accepted: its face plane (as face.c computes it) and mesh data.
struct Tri {
    std::array<Vec, 3> v;
    Vec norm;
    double offset = 0;
    int ax = 0;
    int flags = kHasV;
    std::array<Vec, 3> n{};
    std::array<UV, 3> uv{};
    int32_t material = kVoid;
    int32_t meshId = -1;  // assigned when the octree walk first meets it
};

enum class Flatness { Flat, Bent, ReversedFlat, ReversedBent, Degenerate };

Flatness classify(const Vec& v1, const Vec& v2, const Vec& v3, const Vec& n1, const Vec& n2,
                  const Vec& n3) {
    Vec vn = cross(sub(v2, v1), sub(v3, v2));
    if (radgeom::normalize(vn) == 0.0) return Flatness::Degenerate;
    double d1 = dot(vn, n1), d2 = dot(vn, n2), d3 = dot(vn, n3);
    if (d1 < 0 && d2 < 0 && d3 < 0) {
        if (d1 > -kCosTol || d2 > -kCosTol || d3 > -kCosTol) return Flatness::ReversedBent;
        return Flatness::ReversedFlat;
    }
    if (d1 < kCosTol || d2 < kCosTol || d3 < kCosTol) return Flatness::Bent;
    return Flatness::Flat;
}

// cvtri(): normals that all face away reverse the triangle, normals that all agree
// with the face are dropped (flat), degenerate and zero-area triangles are skipped.
bool accept(const MeshTriangleInput& in, Tri& t) {
    Vec v1 = in.v[0], v2 = in.v[1], v3 = in.v[2];
    Vec n1 = in.n[0], n2 = in.n[1], n3 = in.n[2];
    UV c1 = in.uv[0], c2 = in.uv[1], c3 = in.uv[2];
    int flags = kHasV;
    if (in.hasNormals) {
        switch (classify(v1, v2, v3, n1, n2, n3)) {
            case Flatness::Bent:
                flags |= kHasN;
                break;
            case Flatness::Flat:
                break;
            case Flatness::ReversedBent:
                flags |= kHasN;
                std::swap(n1, n3);
                [[fallthrough]];
            case Flatness::ReversedFlat:
                std::swap(v1, v3);
                std::swap(c1, c3);
                break;
            case Flatness::Degenerate:
                warn(in.loc, "degenerate triangle");
                return false;
        }
    }
    if (in.hasUV) flags |= kHasUV;
    t.v = {v1, v2, v3};
    t.norm = cross(sub(v2, v1), sub(v3, v1));
    if (radgeom::normalize(t.norm) == 0.0) {
        warn(in.loc, "zero-area triangle");
        return false;
    }
    t.offset = dot(t.norm, v1);
    t.offset += dot(t.norm, v2);
    t.offset += dot(t.norm, v3);
    t.offset /= 3.0;
    t.ax = std::fabs(t.norm[1]) > std::fabs(t.norm[0]);
    if (std::fabs(t.norm[2]) > std::fabs(t.norm[t.ax])) t.ax = 2;
    t.flags = flags;
    if (flags & kHasN) t.n = {n1, n2, n3};
    if (flags & kHasUV) t.uv = {c1, c2, c3};
    t.material = in.material;
    return true;
}

// o_face.c: does the triangle meet the cube (grown by FTINY)?
bool faceHitsCube(const Tri& f, const Vec& org, double size) {
    const double va[9] = {f.v[0][0], f.v[0][1], f.v[0][2], f.v[1][0], f.v[1][1],
                          f.v[1][2], f.v[2][0], f.v[2][1], f.v[2][2]};
    return radgeom::faceMeetsCube(va, 3, f.norm, f.offset, f.ax, org, size);
}

class Builder {
public:
    Builder(const MeshWriteOptions& opt, std::vector<Tri>& tris, BuiltMesh& mesh)
        : opt_(opt), tris_(tris), mesh_(mesh) {}

    void addFace(const Vec& org, double size, Node& node, int32_t obj) {
        if (!faceHitsCube(tris_[obj], org, size)) return;
        if (isTree(node)) {
            double half = size * 0.5;
            for (int i = 0; i < 8; ++i) {
                Node kid = mesh_.tree.trees[node][i];
                addFace(kidOrigin(org, half, i), half, kid, obj);
                mesh_.tree.trees[node][i] = kid;
            }
            return;
        }
        if (node == kEmpty) {
            mesh_.tree.sets.push_back({obj});
            node = -static_cast<Node>(mesh_.tree.sets.size() - 1) - 2;
            return;
        }
        addToLeaf(org, size, node, obj);
    }

    // Merges subtrees whose eight children are the same leaf (octree.c combine()).
    Node combine(Node node) {
        if (!isTree(node)) return node;
        Node result = mesh_.tree.trees[node][0] = combine(mesh_.tree.trees[node][0]);
        for (int i = 1; i < 8; ++i) {
            Node kid = mesh_.tree.trees[node][i] = combine(mesh_.tree.trees[node][i]);
            if (!sameLeaf(kid, result)) result = node;
        }
        return result;
    }

    // Replaces input indices in leaves by mesh triangle IDs, adding triangles to
    // patches in the order RADIANCE's cvmeshoct() meets them (children 7 to 0, each
    // leaf's triangles from the last one input).
    void convert(Node node) {
        if (node == kEmpty) return;
        if (isLeaf(node)) {
            std::vector<int32_t>& set = mesh_.tree.sets[setIndex(node)];
            std::vector<int32_t> ids;
            for (size_t i = set.size(); i-- > 0;) ids.push_back(meshTriangle(set[i]));
            std::sort(ids.begin(), ids.end());
            set = std::move(ids);
            return;
        }
        for (int i = 8; i-- > 0;) convert(mesh_.tree.trees[node][i]);
    }

private:
    static Vec kidOrigin(const Vec& org, double half, int i) {
        Vec o = org;
        for (int j = 0; j < 3; ++j)
            if ((1 << j) & i) o[j] += half;
        return o;
    }

    bool sameLeaf(Node a, Node b) const {
        if (a == b) return true;
        return isLeaf(a) && isLeaf(b) &&
               mesh_.tree.sets[setIndex(a)] == mesh_.tree.sets[setIndex(b)];
    }

    void addToLeaf(const Vec& org, double size, Node& node, int32_t obj) {
        std::vector<int32_t> set = mesh_.tree.sets[setIndex(node)];
        double half = size * 0.5;
        double minSize = octree::smallestCell(mesh_.cubeSize, opt_.maxres);
        if (set.size() < static_cast<size_t>(opt_.objlim) ||
            half < (set.size() < kMaxSet ? minSize : minSize / 256.0)) {
            if (set.size() >= kMaxSet)
                throw InputError("more than 511 triangles in one octree cube (raise -r)");
            auto& s = mesh_.tree.sets[setIndex(node)];
            s.insert(std::upper_bound(s.begin(), s.end(), obj), obj);
            return;
        }
        mesh_.tree.trees.push_back(
            {kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty});
        Node tree = static_cast<Node>(mesh_.tree.trees.size() - 1);
        for (int i = 0; i < 8; ++i) {
            Node kid = kEmpty;
            Vec ko = kidOrigin(org, half, i);
            for (int32_t o : set) addFace(ko, half, kid, o);
            addFace(ko, half, kid, obj);
            mesh_.tree.trees[tree][i] = kid;
        }
        node = tree;
    }

    struct VertexKey {
        int fl;
        std::array<uint32_t, 3> xyz;
        int32_t norm;
        std::array<uint32_t, 2> uv;
        bool operator<(const VertexKey& o) const {
            return std::tie(fl, xyz, norm, uv) < std::tie(o.fl, o.xyz, o.norm, o.uv);
        }
    };

    // addmeshvert(): the vertex ID (patch << 8 | index), or -1 outside the limits.
    int32_t vertex(int fl, const Vec& v, const Vec& n, const UV& uv) {
        VertexKey key{fl, {}, 0, {}};
        for (int i = 0; i < 3; ++i) {
            if (v[i] < mesh_.cubeOrigin[i]) return -1;
            if (v[i] >= mesh_.cubeOrigin[i] + mesh_.cubeSize) return -1;
            // RADIANCE multiplies first, then divides; keep its rounding.
            key.xyz[i] = static_cast<uint32_t>(static_cast<uint64_t>(
                4294967296.0 * (v[i] - mesh_.cubeOrigin[i]) / mesh_.cubeSize));
        }
        if (fl & kHasN) key.norm = encodeDirection(n);
        if (fl & kHasUV) {
            for (int i = 0; i < 2; ++i) {
                const double lo = mesh_.uvLimits[0][i], hi = mesh_.uvLimits[1][i];
                if (uv[i] <= lo || uv[i] >= hi) return -1;
                key.uv[i] = static_cast<uint32_t>(
                    static_cast<uint64_t>(4294967296.0 * (uv[i] - lo) / (hi - lo)));
            }
        }
        auto [it, added] = vertices_.emplace(key, 0);
        if (!added) return it->second;
        auto& patches = mesh_.patches;
        if (patches.empty() || patches.back().xyz.size() >= 256) {
            if (patches.size() >= (size_t{1} << 22)) throw InputError("too many mesh patches");
            patches.emplace_back();
        }
        Patch& p = patches.back();
        p.xyz.push_back(key.xyz);
        p.norm.push_back(key.norm);
        p.uv.push_back(key.uv);
        p.hasNorm |= (fl & kHasN) != 0;
        p.hasUV |= (fl & kHasUV) != 0;
        it->second = static_cast<int32_t>((patches.size() - 1) << 8 | (p.xyz.size() - 1));
        return it->second;
    }

    int32_t meshTriangle(int32_t obj) {
        Tri& t = tris_[obj];
        if (t.meshId >= 0) return t.meshId;
        std::array<int32_t, 3> vid;
        std::array<int, 3> pn;
        for (int i = 0; i < 3; ++i) {
            vid[i] = vertex(t.flags, t.v[i], t.n[i], t.uv[i]);
            if (vid[i] < 0) throw InputError("mesh triangle vertex outside the mesh bounds");
            pn[i] = vid[i] >> 8;
        }
        int32_t mo = t.material;
        if (mo != kVoid && mo + 1 > mesh_.nmats) mesh_.nmats = mo + 1;
        t.meshId = addTriangle(vid, pn, static_cast<int16_t>(mo));
        return t.meshId;
    }

    // addmeshtri(): local triangle, single joiner (two corners in one patch) or
    // double joiner, stored in the patch RADIANCE picks.
    int32_t addTriangle(std::array<int32_t, 3> vid, std::array<int, 3> pn, int16_t mo) {
        auto& patches = mesh_.patches;
        if (pn[0] == pn[1] && pn[1] == pn[2]) {
            Patch& p = patches[pn[0]];
            if (p.tri.size() < 512) {
                p.tri.push_back({static_cast<uint8_t>(vid[0] & 0xff),
                                 static_cast<uint8_t>(vid[1] & 0xff),
                                 static_cast<uint8_t>(vid[2] & 0xff)});
                size_t k = p.tri.size() - 1;
                if (k == 0)
                    p.solemat = mo;
                else if (p.trimat.empty() && mo != p.solemat)
                    p.trimat.assign(k, p.solemat);
                if (!p.trimat.empty()) p.trimat.push_back(mo);
                return pn[0] << 10 | static_cast<int32_t>(k);
            }
        } else if (pn[0] == pn[1]) {
            vid = {vid[2], vid[0], vid[1]};
            pn = {pn[2], pn[0], pn[1]};
        } else if (pn[0] == pn[2]) {
            vid = {vid[1], vid[2], vid[0]};
            pn = {pn[1], pn[2], pn[0]};
        }
        if (pn[1] == pn[2]) {
            Patch& p = patches[pn[1]];
            if (p.j1.size() < 256) {
                p.j1.push_back({vid[0], mo, static_cast<uint8_t>(vid[1] & 0xff),
                                static_cast<uint8_t>(vid[2] & 0xff)});
                return pn[1] << 10 | 0x200 | static_cast<int32_t>(p.j1.size() - 1);
            }
        }
        int i = 0;
        if (patches[pn[1]].j2.size() < patches[pn[i]].j2.size()) i = 1;
        if (patches[pn[2]].j2.size() < patches[pn[i]].j2.size()) i = 2;
        Patch& p = patches[pn[i]];
        if (p.j2.size() >= 256) throw InputError("too many joiner triangles in one mesh patch");
        Patch::Join2 j{};
        j.mat = mo;
        switch (i) {
            case 0:
                j.v3 = vid[0] & 0xff;
                j.v1j = vid[1];
                j.v2j = vid[2];
                break;
            case 1:
                j.v2j = vid[0];
                j.v3 = vid[1] & 0xff;
                j.v1j = vid[2];
                break;
            default:
                j.v1j = vid[0];
                j.v2j = vid[1];
                j.v3 = vid[2] & 0xff;
                break;
        }
        p.j2.push_back(j);
        return pn[i] << 10 | 0x300 | static_cast<int32_t>(p.j2.size() - 1);
    }

    const MeshWriteOptions& opt_;
    std::vector<Tri>& tris_;
    BuiltMesh& mesh_;
    std::map<VertexKey, int32_t> vertices_;
};

}  // namespace

BuiltMesh buildMesh(const MeshSource& source, const MeshWriteOptions& options) {
    if (options.objlim < 1) throw InputError("objlim must be at least 1");
    if (options.maxres < 1) throw InputError("maxres must be at least 1");
    const int32_t nprims = static_cast<int32_t>(source.materials.prims.size());
    std::vector<Tri> tris;
    tris.reserve(source.triangles.size());
    Vec lo{kHuge, kHuge, kHuge}, hi{-kHuge, -kHuge, -kHuge};
    BuiltMesh mesh;
    mesh.uvLimits = {{{kHuge, kHuge}, {-kHuge, -kHuge}}};
    for (const MeshTriangleInput& in : source.triangles) {
        if (in.material != kVoid && (in.material < 0 || in.material >= nprims))
            throw InputError(in.loc, "triangle material index out of range");
        Tri t;
        if (!accept(in, t)) continue;
        for (int k = 0; k < 3; ++k) {
            for (int j = 0; j < 3; ++j) {
                lo[j] = std::min(lo[j], t.v[k][j]);
                hi[j] = std::max(hi[j], t.v[k][j]);
            }
            if (t.flags & kHasUV)
                for (int j = 0; j < 2; ++j) {
                    mesh.uvLimits[0][j] = std::min(mesh.uvLimits[0][j], t.uv[k][j]);
                    mesh.uvLimits[1][j] = std::max(mesh.uvLimits[1][j], t.uv[k][j]);
                }
        }
        tris.push_back(t);
    }
    if (tris.empty()) throw InputError("no triangles in mesh");
    // cvmeshbounds(): a cube around the bounds grown by 10*FTINY, centred on them.
    constexpr double kMargin = 10 * kTiny;
    for (int i = 0; i < 3; ++i) {
        lo[i] -= kMargin;
        hi[i] += kMargin;
        if (hi[i] - lo[i] > mesh.cubeSize) mesh.cubeSize = hi[i] - lo[i];
    }
    for (int i = 0; i < 3; ++i) mesh.cubeOrigin[i] = (hi[i] + lo[i] - mesh.cubeSize) * .5;
    auto& uvl = mesh.uvLimits;
    if (uvl[0][0] > uvl[1][0]) {
        uvl = {};
    } else {
        for (int i = 0; i < 2; ++i) {
            double margin = (2. / 65536.) * (uvl[1][i] - uvl[0][i]) + kTiny;
            uvl[0][i] -= margin;
            uvl[1][i] += margin;
        }
    }
    Builder b(options, tris, mesh);
    for (int32_t i = 0; i < static_cast<int32_t>(tris.size()); ++i)
        b.addFace(mesh.cubeOrigin, mesh.cubeSize, mesh.tree.root, i);
    mesh.tree.root = b.combine(mesh.tree.root);
    if (mesh.tree.root == kEmpty) warn("mesh is empty");
    b.convert(mesh.tree.root);
    for (int32_t m = 0; m < mesh.nmats; ++m) {
        const Primitive& p = source.materials.prims[m];
        if (!isModifier(p.type))
            throw InputError(p.loc, "non-modifier in mesh (" + std::string(primTypeName(p.type)) +
                                        " \"" + p.name + "\")");
    }
    bool noUVBounds = uvl[1][0] - uvl[0][0] <= kTiny || uvl[1][1] - uvl[0][1] <= kTiny;
    for (const Patch& p : mesh.patches)
        if (noUVBounds && p.hasUV) throw InputError("(u, v) coordinates span no area");
    return mesh;
}

}  // namespace rp::meshbuild
