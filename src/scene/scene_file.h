// Our own frozen scene file (header FORMAT=radphoton_scene, then a versioned binary
// payload of all records), which oconv wrote before it wrote RADIANCE's octrees; it is
// still read (and written by pkgBSDF). And what loading needs of RADIANCE's octrees
// (FORMAT=Radiance_octree, which our oconv now writes: octree_file.h): the scene file
// names a non-frozen octree lists, a frozen octree's objects, the cube.
// Deciding which kind a file is, and loading it, is loadScene() in scene_load.h.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "scene/primitive.h"
#include "util/header.h"

namespace rp {

constexpr const char* kSceneFileFormat = "radphoton_scene";
constexpr const char* kRadianceOctreeFormat = "Radiance_octree";
constexpr uint32_t kSceneFileVersion = 1;

// The binary payload alone (what follows the header).
std::string encodeScene(const Scene& scene);
// Decodes a payload; magic, version, every count and index are validated, so a
// truncated or corrupted file is an InputError naming `what`, never a crash.
Scene decodeScene(std::string_view payload, const std::string& what);

// Header (the given lines, then FORMAT=radphoton_scene) followed by the payload.
std::string sceneFileBytes(const Scene& scene, const std::vector<std::string>& headerLines);
// Writes sceneFileBytes to `path` through a temporary file in the same folder and a
// rename, so a failed write never leaves a half-written scene file behind.
void saveSceneFile(const std::string& path, const Scene& scene,
                   const std::vector<std::string>& headerLines);

// Splits a file's bytes into its RADIANCE header and the rest. False if the bytes do
// not start with a "#?RADIANCE" header.
bool splitHeader(std::string_view bytes, Header& header, std::string_view& rest);

// The scene file names stored in a RADIANCE octree after its header (readoct.c: a
// 2-byte magic giving the object size, four boundary strings, then NUL-terminated
// names ending with an empty one). Empty for a frozen octree (oconv -f, or input from
// standard input), whose objects are stored in binary instead.
std::vector<std::string> radianceOctreeFiles(std::string_view binary, const std::string& what);

// The objects of a frozen RADIANCE octree (readoct.c): after the file list (empty), the
// object count, the octree (skipped; its structure and object references are checked),
// then the binary object records (radiance_objects.h), which must number as many as the
// count says. Throws InputError naming `what` for anything truncated or damaged.
Scene decodeRadianceFrozenOctree(std::string_view binary, const std::string& what);

// The cube of a RADIANCE octree or compiled mesh: what follows the 2-byte magic number
// in both (the origin x, y, z and the side as decimal strings). `text` keeps the strings
// as stored, which getinfo -d prints. Throws InputError naming `what` if the magic
// number is not that of an octree (mesh = false) or a mesh (mesh = true), or the cube
// is truncated or not numbers.
struct RadianceCube {
    std::array<double, 3> origin{};
    double size = 0;
    std::array<std::string, 4> text;
};
RadianceCube radianceCube(std::string_view binary, bool mesh, const std::string& what);

}  // namespace rp
