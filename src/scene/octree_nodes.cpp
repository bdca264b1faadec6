#include "scene/octree_nodes.h"

#include <cmath>

#include "scene/radiance_geom.h"
#include "util/error.h"
#include "util/portable_io.h"

namespace rp::octree {

double smallestCell(double cubeSize, int maxres) {
    if (!std::isfinite(cubeSize))
        throw InputError("the scene's bounds are not finite (coordinates beyond double range)");
    const double radiance = cubeSize / maxres - radgeom::kTiny;
    return radiance > 0 ? radiance : cubeSize / maxres;
}

// An explicit stack rather than recursion: each entry is a node still to write.
void putOctreeNodes(std::string& out, const OctreeNodes& t, int objsize) {
    std::vector<Node> stack{t.root};
    while (!stack.empty()) {
        const Node n = stack.back();
        stack.pop_back();
        if (isTree(n)) {
            out.push_back(char(kTreeNode));
            const auto& kids = t.trees[size_t(n)];
            for (size_t i = 8; i-- > 0;) stack.push_back(kids[i]);
        } else if (isLeaf(n)) {
            out.push_back(char(kTreeFull));
            const auto& set = t.sets[setIndex(n)];
            portable::putInt(out, int64_t(set.size()), objsize);
            for (int32_t o : set) portable::putInt(out, o, objsize);
        } else {
            out.push_back(char(kTreeEmpty));
        }
    }
}

}  // namespace rp::octree
