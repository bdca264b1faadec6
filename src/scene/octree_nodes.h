// The nodes of a RADIANCE octree (common/octree.h) as both of RADIANCE's octrees use them:
// the scene octree oconv writes (octree_build.h) and the triangle octree inside a compiled
// mesh (mesh_build.h); and writing them out (writeoct.c puttree, cvmesh's the same).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rp::octree {

// A node as RADIANCE codes it: kEmpty, a tree (index >= 0 into OctreeNodes::trees) or a
// leaf (value <= -2: set -value-2 in OctreeNodes::sets).
using Node = int32_t;
constexpr Node kEmpty = -1;
inline bool isTree(Node n) { return n >= 0; }
inline bool isLeaf(Node n) { return n < kEmpty; }
inline size_t setIndex(Node n) { return static_cast<size_t>(-n - 2); }
inline Node leafNode(size_t set) { return -static_cast<Node>(set) - 2; }

constexpr size_t kMaxSet = 511;  // object.h MAXSET: the most objects a leaf holds

// The node kinds in a file (octree.h OT_EMPTY, OT_FULL, OT_TREE).
constexpr int kTreeEmpty = 0, kTreeFull = 1, kTreeNode = 2;

struct OctreeNodes {
    Node root = kEmpty;
    std::vector<std::array<Node, 8>> trees;
    std::vector<std::vector<int32_t>> sets;  // object (or triangle) numbers, ascending
};

// The size below which a cell is not split (unless its set is full): RADIANCE's cube
// size / maxres - FTINY, or size / maxres where that is not positive. RADIANCE's own
// limit is not positive for a cube under maxres x FTINY, where its oconv and obj2mesh
// split objects meeting at a point without end until the stack overflows; elsewhere
// nothing changes. InputError for a cube that is not finite (coordinates overflowing).
double smallestCell(double cubeSize, int maxres);

// Appends the nodes in pre-order, as RADIANCE writes them: a kind byte each, and for a
// leaf its set size and members as `objsize`-byte integers.
void putOctreeNodes(std::string& out, const OctreeNodes& t, int objsize);

}  // namespace rp::octree
