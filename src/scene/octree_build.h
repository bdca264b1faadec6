// RADIANCE's octree over a scene's surfaces, built as RADIANCE's oconv builds it
// (ot/oconv.c): objects are added one at a time, in order, to every cube they meet; a
// leaf holding objlim objects or more splits into eight when the new object does not
// enclose it and the halves are not below the size limit; then identical leaves
// merge (octree.c combine). Writing the tree out is octree_file.h.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/octree_shapes.h"

namespace rp::octree {

// A node as RADIANCE codes it: kEmpty, a tree (index >= 0 into Octree::trees) or a leaf
// (value <= -2: set -value-2 in Octree::sets).
using Node = int32_t;
constexpr Node kEmpty = -1;
inline bool isTree(Node n) { return n >= 0; }
inline bool isLeaf(Node n) { return n < kEmpty; }
inline size_t setIndex(Node n) { return static_cast<size_t>(-n - 2); }
inline Node leafNode(size_t set) { return -static_cast<Node>(set) - 2; }

constexpr size_t kMaxSet = 511;  // object.h MAXSET: the most objects a leaf holds

struct Octree {
    Cube cube;
    Node root = kEmpty;
    std::vector<std::array<Node, 8>> trees;
    std::vector<std::vector<int32_t>> sets;  // object numbers, ascending
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
