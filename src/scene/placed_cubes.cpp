// See placed_cubes.h.
#include "scene/placed_cubes.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "scene/octree_build.h"
#include "scene/octree_file.h"
#include "scene/scene_file.h"
#include "scene/scene_load.h"
#include "util/file_read.h"
#include "util/header.h"

namespace rp {

namespace {

// A cube value written as oconv writes it ("%.12g") and read back.
double throughText(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.12g", v);
    return std::strtod(buf, nullptr);
}

}  // namespace

void conesAsRadianceSeesThem(Scene& scene, size_t first) {
    for (size_t i = first; i < scene.prims.size(); ++i) {
        Primitive& p = scene.prims[i];
        if ((p.type != PrimType::Cone && p.type != PrimType::Cup) || p.rargs.size() != 8) continue;
        if (std::fabs(p.rargs[7] - p.rargs[6]) > radgeom::kTiny) continue;
        p.type = p.type == PrimType::Cone ? PrimType::Cylinder : PrimType::Tube;
        p.rargs.resize(7);
    }
}

octree::Cube PlacedCubes::operator()(const Primitive& p) {
    const bool mesh = p.type == PrimType::Mesh;
    const std::string path = findPlacedFile(p, dirs_);
    const std::string key = (mesh ? "m:" : "o:") + path;
    if (auto it = cubes_.find(key); it != cubes_.end()) return it->second;
    octree::Cube cube;
    try {
        cube = mesh ? fileCube(path, true) : octreeCube(path);
    } catch (const InputError& e) {
        throw InputError(p.loc,
                         std::string(primTypeName(p.type)) + " '" + p.name + "': " + e.what());
    }
    cubes_[key] = cube;
    return cube;
}

// The cube stored at the start of an octree or mesh file.
octree::Cube PlacedCubes::fileCube(const std::string& path, bool mesh) {
    for (size_t limit : {size_t(65536), size_t(0)}) {
        const std::string bytes = readFileBytes(path, limit);
        Header header;
        std::string_view rest;
        const bool whole = limit == 0 || bytes.size() < limit;
        if (!splitHeader(bytes, header, rest)) {
            if (!whole) continue;
            throw InputError(SourceLoc{path, 0}, mesh ? "not a mesh" : "not an octree");
        }
        const char* want = mesh ? "Radiance_tmesh" : kRadianceOctreeFormat;
        if (header.format() != want)
            throw InputError(SourceLoc{path, 0},
                             std::string(mesh ? "not a mesh" : "not an octree") +
                                 " (FORMAT=" + header.format() + ")");
        try {
            const RadianceCube c = radianceCube(rest, mesh, path);
            return {c.origin, c.size};
        } catch (const InputError&) {
            if (whole) throw;
        }
    }
    return {};
}

// An instance's octree: RADIANCE's, or our older scene file, whose cube is the one
// oconv would have made for its records.
octree::Cube PlacedCubes::octreeCube(const std::string& path) {
    const std::string head = readFileBytes(path, 4096);
    Header header;
    std::string_view rest;
    if (!splitHeader(head, header, rest) || header.format() != kSceneFileFormat)
        return fileCube(path, false);
    if (!loading_.insert(path).second) throw InputError(SourceLoc{path, 0}, "octree places itself");
    const std::string bytes = readFileBytes(path);
    splitHeader(bytes, header, rest);
    Scene s = decodeScene(rest, path);
    conesAsRadianceSeesThem(s, 0);
    const octree::Shapes shapes(s, s.prims.size(),
                                [this](const Primitive& q) { return (*this)(q); });
    octree::Cube cube = octree::sceneCube(shapes, 0, int32_t(s.prims.size()));
    loading_.erase(path);
    // As RADIANCE would read it back from the octree oconv would have written.
    for (double& c : cube.org) c = throughText(c);
    cube.size = throughText(cube.size);
    return cube;
}

}  // namespace rp
