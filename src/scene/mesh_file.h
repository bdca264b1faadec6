// TEMPORARY stand-in until the mesh reader lands.
#pragma once
#include <string>
#include "scene/mesh_data.h"
namespace rp {
MeshData readMeshFile(const std::string& path);
}
