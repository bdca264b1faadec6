// RADIANCE's binary scene records (common/sceneio.c readscene/writescene): the objects
// that follow the octree in a frozen octree (oconv -f) and the materials in a compiled
// mesh (.rtm). Shared by the octree reader (scene_file.h), the mesh reader and writer
// (mesh_file.h).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "scene/primitive.h"

namespace rp {

// Decodes the records that start at bytes[pos] (object references `objsize` bytes
// wide, as the file's magic number says), up to and including the end mark, and moves
// pos past them. Modifier references are resolved into the returned Scene's indices
// (kVoid for void); aliases are resolved as RADIANCE's reader resolves them. Every
// count, index and string is checked: a truncated or damaged file is an InputError
// naming `what`, never a crash.
Scene decodeRadianceObjects(std::string_view bytes, size_t& pos, int objsize,
                            const std::string& what);

// Appends the records of `scene` (modifier indices into its own prims, kVoid for void)
// to out in the same format, with `objsize`-byte object references, and the end mark.
void encodeRadianceObjects(const Scene& scene, int objsize, std::string& out);

}  // namespace rp
