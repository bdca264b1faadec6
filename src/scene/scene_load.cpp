// loadScene() and oconv's work (see scene_load.h).
#include "scene/scene_load.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <unordered_map>

#include "calc/search_path.h"
#include "scene/mesh_data.h"
#include "scene/mesh_file.h"
#include "scene/scene_file.h"
#include "util/file_read.h"
#include "util/paths.h"

namespace rp {

namespace {

void loadRadianceOctree(SceneReader& reader, const std::string& path, std::string_view binary) {
    std::vector<std::string> files = radianceOctreeFiles(binary, path);
    if (files.empty()) {
        // oconv -f: the objects are stored in the octree itself.
        reader.append(decodeRadianceFrozenOctree(binary, path));
        return;
    }
    for (const auto& f : files) {
        // RADIANCE's readoct() opens the names as stored, relative to the current folder.
        if (f[0] != '!' && ::access(f.c_str(), R_OK) != 0)
            throw InputError(SourceLoc{path, 0}, "cannot open scene file '" + f +
                                                     "' named in the octree (" +
                                                     std::strerror(errno) + ")");
        reader.readFile(f);
    }
}

// Returns the header lines of the file (empty for text), after loading it into reader.
std::vector<std::string> loadOne(SceneReader& reader, const std::string& path) {
    if (path == "-" || (!path.empty() && path[0] == '!')) {
        reader.readFile(path);
        return {};
    }
    std::string bytes = readFileBytes(path);
    Header header;
    std::string_view rest;
    if (!splitHeader(bytes, header, rest)) {
        // Scene text has no NUL bytes; scene files and octrees do. One whose header was
        // damaged must not be read as text, whose "!" lines would go to the shell.
        if (bytes.find('\0') != std::string::npos)
            throw InputError(SourceLoc{path, 0},
                             "binary data, not a scene description (a scene file or octree "
                             "with a damaged header?)");
        reader.readContents(path, bytes);
        return {};
    }
    std::string format = header.format();
    if (format == kSceneFileFormat) {
        reader.append(decodeScene(rest, path));
    } else if (format == kRadianceOctreeFormat) {
        loadRadianceOctree(reader, path, rest);
    } else {
        throw InputError(SourceLoc{path, 0},
                         "not a scene description, scene file or octree (FORMAT=" + format + ")");
    }
    reader.addInput({path, fileMtime(path)});
    return header.lines;
}
}  // namespace

Scene loadScene(const std::vector<std::string>& paths, const LoadOptions& options) {
    SceneReader reader(options);
    for (const auto& p : paths) loadOne(reader, p);
    Scene scene = reader.take();
    attachObjects(scene, calc::defaultSearchPath(projectLibDir()), options);
    return scene;
}

std::string findPlacedFile(const Primitive& p, const std::vector<std::string>& dirs) {
    const std::string what = p.type == PrimType::Mesh ? "mesh" : "octree";
    const std::string header = std::string(primTypeName(p.type)) + " '" + p.name + "': ";
    if (p.sargs.empty()) throw InputError(p.loc, header + "no " + what + " file");
    auto found = calc::findFile(p.sargs[0], dirs);
    if (!found)
        throw InputError(p.loc, header + "cannot find " + what + " file '" + p.sargs[0] + "'");
    return *found;
}

namespace {

bool isLightType(PrimType t) {
    return t == PrimType::Light || t == PrimType::Illum || t == PrimType::Glow ||
           t == PrimType::Spotlight;
}

// attachObjects' state: the files loaded so far and the chain of octrees being loaded.
class ObjectLoader {
public:
    ObjectLoader(Scene& scene, const std::vector<std::string>& dirs, const LoadOptions& options)
        : scene_(scene), dirs_(dirs), options_(options) {}

    // Places the objects named by the instance and mesh records in [begin, end).
    void placeAll(int32_t begin, int32_t end) {
        for (int32_t i = begin; i < end; ++i) {
            const PrimType t = scene_.prims[size_t(i)].type;
            if (t != PrimType::Instance && t != PrimType::Mesh) continue;
            checkModifier(scene_.prims[size_t(i)]);
            const int32_t object = objectFor(i);
            scene_.prims[size_t(i)].placed = object;
        }
    }

private:
    void checkModifier(const Primitive& p) const {
        // RADIANCE compat: lights inside instances and meshes glow but are not sources,
        // so a light modifier on the placing primitive itself would emit nothing.
        if (p.modifier != kVoid && isLightType(scene_.prims[size_t(p.modifier)].type))
            throw InputError(p.loc, std::string(primTypeName(p.type)) + " '" + p.name +
                                        "': cannot be modified by light material '" +
                                        scene_.prims[size_t(p.modifier)].name + "'");
    }

    int32_t objectFor(int32_t placing) {
        const Primitive& p = scene_.prims[size_t(placing)];
        const bool mesh = p.type == PrimType::Mesh;
        const SourceLoc loc = p.loc;
        const std::string header = std::string(primTypeName(p.type)) + " '" + p.name + "': ";
        const std::string found = findPlacedFile(p, dirs_);
        const std::string key = (mesh ? "m:" : "o:") + found;
        for (const auto& open : loading_)
            if (open == found)
                throw InputError(loc, header + "octree '" + found + "' places itself");
        if (auto it = loaded_.find(key); it != loaded_.end()) return it->second;

        SceneObject object;
        object.kind = mesh ? SceneObject::Kind::Mesh : SceneObject::Kind::Octree;
        object.path = found;
        Scene contents;
        try {
            if (mesh) {
                auto data = std::make_shared<MeshData>(readMeshFile(found));
                contents = data->materials;
                object.mesh = std::move(data);
                contents.inputs.push_back({found, fileMtime(found)});
            } else {
                contents = loadOctree(found);
            }
        } catch (const InputError& e) {
            // Where the file was named, then what is wrong with it.
            throw InputError(loc, header + e.what());
        }
        const auto index = int32_t(scene_.objects.size());
        object.firstPrim = int32_t(scene_.prims.size());
        for (Primitive q : contents.prims) {
            if (q.modifier != kVoid) q.modifier += object.firstPrim;
            if (q.aliasOf >= 0) q.aliasOf += object.firstPrim;
            q.object = index;
            scene_.prims.push_back(std::move(q));
        }
        object.endPrim = int32_t(scene_.prims.size());
        scene_.inputs.insert(scene_.inputs.end(), contents.inputs.begin(), contents.inputs.end());
        scene_.objects.push_back(std::move(object));
        loaded_[key] = index;
        if (!mesh) {
            loading_.push_back(found);
            placeAll(scene_.objects[size_t(index)].firstPrim,
                     scene_.objects[size_t(index)].endPrim);
            loading_.pop_back();
        }
        return index;
    }

    // An instance's file: our scene file or a RADIANCE octree, not scene text.
    Scene loadOctree(const std::string& path) {
        std::string bytes = readFileBytes(path);
        Header header;
        std::string_view rest;
        std::string format = splitHeader(bytes, header, rest) ? header.format() : "";
        if (format != kSceneFileFormat && format != kRadianceOctreeFormat)
            throw InputError(
                SourceLoc{path, 0},
                "not an octree" + (format.empty() ? std::string() : " (FORMAT=" + format + ")"));
        SceneReader reader(options_);
        loadOne(reader, path);
        return reader.take();
    }

    Scene& scene_;
    const std::vector<std::string>& dirs_;
    const LoadOptions& options_;
    std::unordered_map<std::string, int32_t> loaded_;  // kind + path -> object
    std::vector<std::string> loading_;                 // octrees whose contents are being placed
};

}  // namespace

void attachObjects(Scene& scene, const std::vector<std::string>& searchPath,
                   const LoadOptions& options) {
    ObjectLoader loader(scene, searchPath, options);
    loader.placeAll(0, scene.ownCount());
}

}  // namespace rp
