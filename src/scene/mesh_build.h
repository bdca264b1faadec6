// The steps of RADIANCE's obj2mesh between reading triangles and writing the file
// (ot/cvmesh.c, ot/obj2mesh.c, common/mesh.c), kept apart from the byte layout
// (mesh_write.cpp) so each can be read on its own. Internal to the mesh writer.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/mesh_write.h"
#include "scene/octree_nodes.h"
#include "util/dir_code.h"

namespace rp::meshbuild {

// The triangle octree: RADIANCE's node coding (leaf sets hold triangle IDs).
using octree::isLeaf;
using octree::isTree;
using octree::kEmpty;
using octree::Node;
using octree::setIndex;
using Octree = octree::OctreeNodes;

// One patch of up to 256 vertices (mesh.h MESHPATCH), with its triangles.
struct Patch {
    std::vector<std::array<uint32_t, 3>> xyz;
    std::vector<int32_t> norm;                // per vertex, 0 = none; used if hasNorm
    std::vector<std::array<uint32_t, 2>> uv;  // per vertex, (0, 0) = none; used if hasUV
    bool hasNorm = false, hasUV = false;
    std::vector<std::array<uint8_t, 3>> tri;
    int16_t solemat = 0;
    std::vector<int16_t> trimat;  // empty while every local triangle has solemat
    struct Join1 {
        int32_t v1j;
        int16_t mat;
        uint8_t v2, v3;
    };
    struct Join2 {
        int32_t v1j, v2j;
        int16_t mat;
        uint8_t v3;
    };
    std::vector<Join1> j1;
    std::vector<Join2> j2;
};

struct BuiltMesh {
    std::array<double, 3> cubeOrigin{};
    double cubeSize = 0;
    std::array<std::array<double, 2>, 2> uvLimits{};
    Octree tree;  // leaf sets hold mesh triangle IDs
    std::vector<Patch> patches;
    int32_t nmats = 0;  // materials 0..nmats-1 are stored
};

BuiltMesh buildMesh(const MeshSource& source, const MeshWriteOptions& options);

// RADIANCE's direction code of a unit vector (util/dir_code.h).
using rp::encodeDirection;

}  // namespace rp::meshbuild
