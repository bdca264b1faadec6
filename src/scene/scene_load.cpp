// loadScene() and oconv's work (see scene_load.h).
#include "scene/scene_load.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "scene/scene_file.h"

namespace rp {

namespace {
std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(SourceLoc{path, 0},
                         std::string("cannot open file (") + std::strerror(errno) + ")");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

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
    std::string bytes = readWholeFile(path);
    Header header;
    std::string_view rest;
    if (!splitHeader(bytes, header, rest)) {
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
    return reader.take();
}

std::string oconvOutput(const OconvRequest& request, const LoadOptions& options) {
    SceneReader reader(options);
    std::vector<std::string> lines;
    if (!request.addTo.empty()) {
        lines = loadOne(reader, request.addTo);
        // The old FORMAT line is replaced by ours at the end.
        std::erase_if(lines, [](const std::string& l) { return l.rfind("FORMAT=", 0) == 0; });
    }
    for (const auto& f : request.files) loadOne(reader, f);
    lines.push_back(request.commandLine);
    return sceneFileBytes(reader.scene(), lines);
}

}  // namespace rp
