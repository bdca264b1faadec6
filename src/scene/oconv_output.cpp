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
#include "scene/placed_cubes.h"
#include "scene/scene_file.h"
#include "scene/scene_load.h"
#include "util/file_read.h"
#include "util/paths.h"
#include "util/warnings.h"

namespace rp {

namespace {

constexpr double kMargin = 10 * radgeom::kTiny;  // oconv.c OMARGIN

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
        : request_(request),
          options_(radianceNumbered(options)),
          reader_(options_),
          placedCubes_(request.searchPath.empty() ? calc::defaultSearchPath(projectLibDir())
                                                  : request.searchPath) {}

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
                              [this](const Primitive& p) { return placedCubes_(p); });
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

    const OconvRequest& request_;
    LoadOptions options_;
    SceneReader reader_;
    std::vector<std::string> files_;
    octree::Octree tree_;
    PlacedCubes placedCubes_;
};

}  // namespace

std::string oconvOutput(const OconvRequest& request, const LoadOptions& options) {
    if (request.maxres < 1) throw InputError("-r must be at least 1");
    return Oconv(request, options).run();
}

}  // namespace rp
