// Reading RADIANCE's compiled triangle meshes (.rtm, FORMAT=Radiance_tmesh, written by
// obj2mesh; common/readmesh.c) into MeshData (mesh_data.h).
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "scene/mesh_data.h"

namespace rp {

constexpr const char* kRadianceMeshFormat = "Radiance_tmesh";

// Reads and decodes the file at `path`. Every problem (missing file, wrong format,
// truncation, damage) is an InputError naming the file.
MeshData readMeshFile(const std::string& path);

// Decodes a whole mesh file's bytes, header included; `what` names it in errors and
// becomes MeshData::path. `consumed`, if given, hears now and then how far into `bytes`
// decoding has got (what lies before is not read again).
MeshData decodeMeshFile(std::string_view bytes, const std::string& what,
                        const std::function<void(size_t)>& consumed = {});

}  // namespace rp
