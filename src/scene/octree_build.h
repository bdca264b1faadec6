// RADIANCE's octree over a scene's surfaces, built as RADIANCE's oconv builds it
// (ot/oconv.c): objects are added one at a time, in order, to every cube they meet; a
// leaf holding objlim objects or more splits into eight when the new object does not
// enclose it and the halves are not below the size limit; then identical leaves
// merge (octree.c combine). Writing the tree out is octree_file.h.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/octree_nodes.h"
#include "scene/octree_shapes.h"

namespace rp::octree {

struct Octree : OctreeNodes {
    Cube cube;
};

struct BuildOptions {
    int objlim = 6;      // oconv -n
    int maxres = 16384;  // oconv -r
};

// oconv's cube for objects [first, end): their bounding box grown by 10*FTINY each way,
// as a cube centred on it (side 0 when no object has extent).
Cube sceneCube(const Shapes& shapes, int32_t first, int32_t end);
// The same box, ungrown, must lie inside `cube` (oconv -b, -i): false if it does not.
bool cubeHolds(const Shapes& shapes, int32_t first, int32_t end, const Cube& cube);

// Adds objects [first, end) to `tree` (its cube set, possibly holding older objects'
// leaves), then merges identical leaves. Throws InputError when a leaf would exceed
// kMaxSet objects.
void addObjects(Octree& tree, Shapes& shapes, const std::vector<Primitive>& prims, int32_t first,
                int32_t end, const BuildOptions& options);

}  // namespace rp::octree
