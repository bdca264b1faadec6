// The steps of RADIANCE's obj2mesh between reading triangles and writing the file
// (ot/cvmesh.c, ot/obj2mesh.c, common/mesh.c), kept apart from the byte layout
// (mesh_write.cpp) so each can be read on its own. Internal to the mesh writer.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/mesh_write.h"
#include "util/dir_code.h"

namespace rp::meshbuild {

// An octree node as RADIANCE codes it: kEmpty, a tree (index >= 0 into Octree::trees),
// or a leaf set (value <= -2, set index -value-2 into Octree::sets).
using Node = int32_t;
constexpr Node kEmpty = -1;
inline bool isTree(Node n) { return n >= 0; }
inline bool isLeaf(Node n) { return n < kEmpty; }
inline size_t setIndex(Node n) { return static_cast<size_t>(-n - 2); }

struct Octree {
    Node root = kEmpty;
    std::vector<std::array<Node, 8>> trees;
    std::vector<std::vector<int32_t>> sets;  // ascending IDs
};

// One patch of up to 256 vertices (mesh.h MESHPATCH), with its triangles.
struct Patch {
    std::vector<std::array<uint32_t, 3>> xyz;
    std::vector<int32_t> norm;                // per vertex, 0 = none; used if hasNorm
    std::vector<std::array<uint32_t, 2>> uv;  // per vertex, (0, 0) = none; used if hasUV
    bool hasNorm = false, hasUV = false;
    std::vector<std::array<uint8_t, 3>> tri;
    int16_t solemat = 0;
    std::vector<int16_t> trimat;  // empty while every local triangle has solemat
    struct Join1 { int32_t v1j; int16_t mat; uint8_t v2, v3; };
    struct Join2 { int32_t v1j, v2j; int16_t mat; uint8_t v3; };
    std::vector<Join1> j1;
    std::vector<Join2> j2;
};

struct BuiltMesh {
    std::array<double, 3> cubeOrigin{};
    double cubeSize = 0;
    std::array<std::array<double, 2>, 2> uvLimits{};
    Octree tree;       // leaf sets hold mesh triangle IDs
    std::vector<Patch> patches;
    int32_t nmats = 0; // materials 0..nmats-1 are stored
};

BuiltMesh buildMesh(const MeshSource& source, const MeshWriteOptions& options);

// RADIANCE's direction code of a unit vector (util/dir_code.h).
using rp::encodeDirection;

}  // namespace rp::meshbuild
