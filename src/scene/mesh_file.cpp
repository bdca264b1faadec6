// TEMPORARY stand-in until the mesh reader lands.
#include "scene/mesh_file.h"
namespace rp {
MeshData readMeshFile(const std::string& path) { throw notSupportedYet(SourceLoc{path, 0}, "mesh files"); }
}
