// One entry point for tools: load a scene from any mix of .rad text files, standard
// input ("-"), "!command"s, our frozen scene files and RADIANCE octrees, telling them
// apart by header, not by extension. Also the work behind the oconv tool.
#pragma once

#include <string>
#include <vector>

#include "scene/primitive.h"
#include "scene/reader.h"

namespace rp {

// Reads the inputs in order into one Scene and attaches the objects its instances and
// meshes place (attachObjects). Scene::inputs lists every file read with its mtime: for
// a frozen scene file, the inputs recorded in it and then the file itself; for a
// RADIANCE octree, the scene files it names and then the octree; then each placed
// octree's inputs and the octree, and each mesh file.
Scene loadScene(const std::vector<std::string>& paths, const LoadOptions& options = {});

// Loads, once per file, every octree (ours or RADIANCE's, frozen or not) and mesh that an
// instance or mesh primitive of the scene names, and those that their instances name,
// appending their records to scene.prims (SceneObject, Primitive::object and ::placed).
// Files are found on `searchPath` as RADIANCE's getpath finds them. A missing file, one
// that is not an octree (instance) or mesh, an octree that places itself, and a light
// material as an instance's or mesh's modifier are InputErrors at the primitive.
void attachObjects(Scene& scene, const std::vector<std::string>& searchPath,
                   const LoadOptions& options = {});

struct OconvRequest {
    std::vector<std::string> files;  // scene descriptions, "-" or "!command"
    std::string addTo;               // -i: existing scene file or octree to add to
    std::string commandLine;         // goes into the header, as RADIANCE's printargs
    // Where instance octrees and meshes are looked for (RADIANCE's getpath); empty: RAYPATH
    // or "." and the project's library.
    std::vector<std::string> searchPath;
};

// What oconv writes: the header (an -i input's header lines first, as RADIANCE's oconv
// copies them) and the frozen scene. As RADIANCE's oconv, it stops at an instance or mesh
// whose file cannot be found (InputError at the primitive).
std::string oconvOutput(const OconvRequest& request, const LoadOptions& options = {});

}  // namespace rp
