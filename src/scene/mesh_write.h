// The compiled mesh writer (RADIANCE obj2mesh's output, FORMAT=Radiance_tmesh): the
// triangles go through the same steps as in RADIANCE's obj2mesh (common/mesh.c,
// ot/cvmesh.c, ot/obj2mesh.c) so that the file matches the one RADIANCE writes for the
// same input: the mesh cube from the bounds, an octree over triangles with objlim
// triangles per leaf down to cube/maxres, patches of at most 256 quantised vertices
// assigned in the order the octree visits the triangles, joiner triangles between
// patches, and the mesh's materials as binary scene records.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/mesh_data.h"
#include "scene/primitive.h"

namespace rp {

// One triangle as a converter hands it over (RADIANCE cvtri's arguments), in double
// precision: vertex positions in order, and normals and (u, v) at each corner when
// every corner has them. Normals must be unit vectors.
struct MeshTriangleInput {
    std::array<std::array<double, 3>, 3> v{};
    std::array<std::array<double, 3>, 3> n{};
    std::array<std::array<double, 2>, 3> uv{};
    bool hasNormals = false;
    bool hasUV = false;
    int32_t material = kVoid;  // index into MeshSource::materials.prims, or kVoid
    SourceLoc loc;             // where it came from (warnings)
};

struct MeshSource {
    std::vector<MeshTriangleInput> triangles;  // in input order
    Scene materials;                           // the -a/-l modifiers, in file order
};

struct MeshWriteOptions {
    int objlim = 9;      // triangles per octree leaf before it is split (obj2mesh -n)
    int maxres = 16384;  // octree resolution limit (obj2mesh -r)
};

// RADIANCE printmeshstats' numbers (obj2mesh -v).
struct MeshStats {
    long materials = 0;
    int patches = 0;
    double megabytes = 0;  // in-memory size as RADIANCE computes it for 64-bit builds
    int vertices = 0, withNormal = 0, withUV = 0;
    int localTris = 0, joinerTris = 0, doubleJoinerTris = 0;
    int fullLeaves = 0, emptyLeaves = 0;
    long leafTriangles = 0;  // sum of leaf set sizes
};
// The text RADIANCE's obj2mesh -v prints to stderr ("Mesh statistics:" and five lines).
std::string formatMeshStats(const MeshStats& s);

// The complete .rtm file: header (the magic line, headerLines, FORMAT=Radiance_tmesh),
// then the binary body with 4-byte object references. Triangles of zero area, and
// triangles whose corner normals are all given but that are degenerate, are dropped
// with a warning, as RADIANCE does. Throws InputError when no triangle remains, a
// triangle's material index is out of range, or a used material is not a modifier.
std::string encodeMeshFile(const MeshSource& source, const MeshWriteOptions& options,
                           const std::vector<std::string>& headerLines, MeshStats* stats = nullptr);

// The same from indexed mesh data (e.g. a mesh read back from a file): each triangle
// takes the normals and (u, v) of its vertices when all three have them.
std::string encodeMeshFile(const MeshData& mesh, int objlim, int maxres,
                           const std::vector<std::string>& headerLines);

// Writes bytes to path through a temporary file renamed into place.
void saveMeshFile(const std::string& path, const std::string& bytes);

}  // namespace rp
