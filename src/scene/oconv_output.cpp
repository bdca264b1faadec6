// oconvOutput() (scene_load.h): RADIANCE's oconv main program (ot/oconv.c) over our
// reader, builder (octree_build.h) and writer (octree_file.h).
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "calc/search_path.h"
#include "scene/octree_file.h"
#include "scene/scene_file.h"
#include "scene/scene_load.h"
#include "util/file_read.h"
#include "util/paths.h"
#include "util/warnings.h"

namespace rp {

namespace {

constexpr double kMargin = 10 * radgeom::kTiny;  // oconv.c OMARGIN

// getcone() makes a cone or cup whose radii are equal a cylinder or tube of 7 arguments,
// in the object itself (so a frozen octree stores it so).
void conesAsRadianceSeesThem(Scene& scene, size_t first) {
    for (size_t i = first; i < scene.prims.size(); ++i) {
        Primitive& p = scene.prims[i];
        if ((p.type != PrimType::Cone && p.type != PrimType::Cup) || p.rargs.size() != 8) continue;
        if (std::fabs(p.rargs[7] - p.rargs[6]) > radgeom::kTiny) continue;
        p.type = p.type == PrimType::Cone ? PrimType::Cylinder : PrimType::Tube;
        p.rargs.resize(7);
    }
}

// A cube value written as oconv writes it ("%.12g") and read back.
double throughText(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.12g", v);
    return std::strtod(buf, nullptr);
}

// RADIANCE's readoct() consistency checks on an octree whose scene files were read again.
void checkReread(const RadianceOctreeFile& old, const Scene& scene, const std::string& path) {
    if (int64_t(scene.prims.size()) != old.objectCount)
        throw InputError(SourceLoc{path, 0}, "bad object count; octree stale?");
    for (const auto& set : old.tree.sets)
        for (int32_t o : set)
            if (!isSurface(scene.prims[size_t(o)].type))
                throw InputError(SourceLoc{path, 0}, "modifier in tree; octree stale?");
}

class Oconv {
public:
    Oconv(const OconvRequest& request, const LoadOptions& options)
        : request_(request), options_(radianceNumbered(options)), reader_(options_) {
        dirs_ = request.searchPath.empty() ? calc::defaultSearchPath(projectLibDir())
                                           : request.searchPath;
    }

    std::string run() {
        std::vector<std::string> lines;
        bool inputFrozen = false;
        if (!request_.addTo.empty()) lines = loadOld(inputFrozen);
        lines.push_back(request_.commandLine);
        const size_t first = reader_.scene().prims.size();
        bool frozen = request_.frozen;
        for (const std::string& f : request_.files) {
            readInput(f);
            if (f == "-")
                frozen = true;  // nothing to read again
            else
                files_.push_back(f);
        }
        if (inputFrozen && !frozen) {
            warn("frozen octree");
            frozen = true;
        }
        Scene scene = reader_.take();
        conesAsRadianceSeesThem(scene, first);
        const auto end = int32_t(scene.prims.size());
        octree::Shapes shapes(scene, size_t(end),
                              [this](const Primitive& p) { return placedCube(p); });
        setCube(shapes, int32_t(first), end);
        octree::addObjects(tree_, shapes, scene.prims, int32_t(first), end,
                           {request_.objlim, request_.maxres});
        return radianceOctreeHeader(lines) +
               encodeRadianceOctree(tree_, end, files_, frozen ? &scene : nullptr);
    }

private:
    static LoadOptions radianceNumbered(LoadOptions o) {
        o.radianceNumbering = true;
        return o;
    }

    // -i: the old octree's header lines (but its FORMAT), tree and objects.
    std::vector<std::string> loadOld(bool& frozen) {
        const std::string& path = request_.addTo;
        if (request_.bounds) throw InputError("only one of '-b' or '-i'");
        const std::string bytes = readFileBytes(path);
        Header header;
        std::string_view rest;
        const std::string format = splitHeader(bytes, header, rest) ? header.format() : "";
        if (format == kSceneFileFormat)
            throw InputError(SourceLoc{path, 0},
                             "a scene file of an older oconv, not an octree: run oconv on "
                             "its scene files again");
        if (format != kRadianceOctreeFormat) throw InputError(SourceLoc{path, 0}, "not an octree");
        RadianceOctreeFile old = decodeRadianceOctree(rest, path);
        frozen = old.files.empty();
        if (frozen) {
            reader_.append(old.objects);
        } else {
            for (const std::string& f : old.files) reader_.readFile(f);
            checkReread(old, reader_.scene(), path);
        }
        files_ = std::move(old.files);
        tree_ = std::move(old.tree);
        std::erase_if(header.lines,
                      [](const std::string& l) { return l.rfind("FORMAT=", 0) == 0; });
        return header.lines;
    }

    // A scene description: text, standard input or a command, never an octree.
    void readInput(const std::string& f) {
        if (f == "-" && request_.standardInput) {
            reader_.readText(*request_.standardInput, "");  // "" names standard input
            return;
        }
        if (f == "-" || f[0] == '!') {
            reader_.readFile(f);
            return;
        }
        const std::string bytes = readFileBytes(f);
        Header header;
        std::string_view rest;
        if (splitHeader(bytes, header, rest))
            throw InputError(SourceLoc{f, 0}, "not a scene description (FORMAT=" + header.format() +
                                                  "); an octree is added to with -i");
        if (bytes.find('\0') != std::string::npos)
            throw InputError(SourceLoc{f, 0}, "binary data, not a scene description");
        reader_.readContents(f, bytes);
    }

    // oconv.c: the cube from the new objects' bounds, or -b's (grown by the margin), or
    // the old octree's; the latter two must hold the new objects.
    void setCube(const octree::Shapes& shapes, int32_t first, int32_t end) {
        if (request_.bounds) {
            const auto& b = *request_.bounds;
            for (int i = 0; i < 3; ++i) tree_.cube.org[size_t(i)] = b[size_t(i)] - kMargin;
            tree_.cube.size = b[3] + 2 * kMargin;
        }
        if (tree_.cube.size == 0.0) {
            tree_.cube = octree::sceneCube(shapes, first, end);
        } else if (!octree::cubeHolds(shapes, first, end, tree_.cube)) {
            throw InputError("boundary does not encompass scene");
        }
    }

    // getinstance()/getmeshinst() with IO_BOUNDS: the cube of the file placed.
    octree::Cube placedCube(const Primitive& p) {
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
    static octree::Cube fileCube(const std::string& path, bool mesh) {
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
    octree::Cube octreeCube(const std::string& path) {
        const std::string head = readFileBytes(path, 4096);
        Header header;
        std::string_view rest;
        if (!splitHeader(head, header, rest) || header.format() != kSceneFileFormat)
            return fileCube(path, false);
        if (!loading_.insert(path).second)
            throw InputError(SourceLoc{path, 0}, "octree places itself");
        const std::string bytes = readFileBytes(path);
        splitHeader(bytes, header, rest);
        Scene s = decodeScene(rest, path);
        conesAsRadianceSeesThem(s, 0);
        const octree::Shapes shapes(s, s.prims.size(),
                                    [this](const Primitive& q) { return placedCube(q); });
        octree::Cube cube = octree::sceneCube(shapes, 0, int32_t(s.prims.size()));
        loading_.erase(path);
        // As RADIANCE would read it back from the octree oconv would have written.
        for (double& c : cube.org) c = throughText(c);
        cube.size = throughText(cube.size);
        return cube;
    }

    const OconvRequest& request_;
    LoadOptions options_;
    SceneReader reader_;
    std::vector<std::string> dirs_;
    std::vector<std::string> files_;
    octree::Octree tree_;
    std::map<std::string, octree::Cube> cubes_;
    std::set<std::string> loading_;
};

}  // namespace

std::string oconvOutput(const OconvRequest& request, const LoadOptions& options) {
    if (request.maxres < 1) throw InputError("-r must be at least 1");
    return Oconv(request, options).run();
}

}  // namespace rp
