// One entry point for tools: load a scene from any mix of .rad text files, standard
// input ("-"), "!command"s, our frozen scene files and RADIANCE octrees, telling them
// apart by header, not by extension. Also the work behind the oconv tool.
#pragma once

#include <array>
#include <optional>
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

// Where an instance's octree or a mesh primitive's mesh file is, as RADIANCE's getpath
// finds it on `dirs`; an InputError at the primitive if nowhere.
std::string findPlacedFile(const Primitive& p, const std::vector<std::string>& dirs);

struct OconvRequest {
    std::vector<std::string> files;  // scene descriptions, "-" or "!command"
    std::string addTo;               // -i: existing RADIANCE octree to add to
    std::string commandLine;         // goes into the header, as RADIANCE's printargs
    // Where instance octrees and meshes are looked for (RADIANCE's getpath); empty: RAYPATH
    // or "." and the project's library.
    std::vector<std::string> searchPath;
    bool frozen = false;  // -f: the objects go into the octree, not the file names
    int objlim = 6;       // -n: objects in a leaf before it splits
    int maxres = 16384;   // -r: the smallest leaf is the cube's side / maxres
    // -b xmin ymin zmin size: the cube (grown by RADIANCE's margin) instead of the bounds.
    std::optional<std::array<double, 4>> bounds;
    // What "-" among the files reads instead of standard input (pkgBSDF's geometry, which
    // RADIANCE's pkgBSDF pipes into `oconv -f -`).
    std::optional<std::string> standardInput;
};

// What RADIANCE's oconv writes (oconv_output.cpp): a RADIANCE octree, header first (an -i
// input's header lines, then the command line, then FORMAT=Radiance_octree). Not frozen,
// it names the scene files, which readers read again; frozen (-f, standard input among
// the files, or -i on a frozen octree) it holds the objects. An -i input must be a
// RADIANCE octree (a scene file of an older oconv is an InputError). Stops at an instance
// or mesh whose file cannot be found or read (InputError at the primitive).
std::string oconvOutput(const OconvRequest& request, const LoadOptions& options = {});

}  // namespace rp
