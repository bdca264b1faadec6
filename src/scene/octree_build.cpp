// See octree_build.h. The order in which a splitting leaf hands its objects to the eight
// new leaves (surfaces, the new object, partly enclosing volumes, enclosing volumes) is
// RADIANCE's, and decides each new leaf's order of splitting, so it is kept exactly.
#include "scene/octree_build.h"

#include <algorithm>
#include <string>

#include "util/error.h"

namespace rp::octree {

namespace {

constexpr double kMargin = 10 * radgeom::kTiny;  // oconv.c OMARGIN

Cube kidCube(const Cube& cu, int i) {
    Cube k;
    k.size = cu.size * 0.5;
    k.org = cu.org;
    for (int j = 0; j < 3; ++j)
        if ((1 << j) & i) k.org[j] += k.size;
    return k;
}

void bounds(const Shapes& shapes, int32_t first, int32_t end, Vec& lo, Vec& hi) {
    lo = {radgeom::kHuge, radgeom::kHuge, radgeom::kHuge};
    hi = {-radgeom::kHuge, -radgeom::kHuge, -radgeom::kHuge};
    for (int32_t i = first; i < end; ++i) shapes.addBounds(i, lo, hi);
}

class Builder {
public:
    Builder(Octree& t, const Shapes& s, const std::vector<Primitive>& prims, int objlim,
            double minCube)
        : t_(t), shapes_(s), prims_(prims), objlim_(objlim), minCube_(minCube) {}

    // oconv.c addobject(): obj into every leaf under `node` (of cube cu) that it meets.
    void add(const Cube& cu, Node& node, int32_t obj) {
        const int inc = shapes_.overlap(obj, cu);
        if (inc == kMiss) return;
        if (isTree(node)) {
            for (int i = 0; i < 8; ++i) {
                Node kid = t_.trees[size_t(node)][size_t(i)];
                add(kidCube(cu, i), kid, obj);
                t_.trees[size_t(node)][size_t(i)] = kid;
            }
            return;
        }
        if (node == kEmpty) {
            node = leafNode(newSet());
            t_.sets[setIndex(node)].push_back(obj);
            return;
        }
        addToLeaf(cu, node, obj, inc);
    }

    // octree.c combine(): a tree whose eight children are the same leaf (or all empty)
    // becomes that leaf.
    Node combine(Node node) {
        if (!isTree(node)) return node;
        auto& kids = t_.trees[size_t(node)];
        Node result = kids[0] = combine(kids[0]);
        for (size_t i = 1; i < 8; ++i) {
            const Node kid = combine(t_.trees[size_t(node)][i]);
            t_.trees[size_t(node)][i] = kid;
            if (!sameLeaf(kid, result)) result = node;
        }
        return result;
    }

private:
    size_t newSet() {
        if (!free_.empty()) {
            const size_t s = free_.back();
            free_.pop_back();
            return s;
        }
        t_.sets.emplace_back();
        return t_.sets.size() - 1;
    }

    bool sameLeaf(Node a, Node b) const {
        if (a == b) return true;
        return isLeaf(a) && isLeaf(b) && t_.sets[setIndex(a)] == t_.sets[setIndex(b)];
    }

    // oconv.c add2full(): the object joins the leaf's set, or the leaf splits.
    void addToLeaf(const Cube& cu, Node& node, int32_t obj, int inc) {
        const size_t si = setIndex(node);
        const size_t n = t_.sets[si].size();
        const double half = cu.size * 0.5;
        if (inc == kInside || n < size_t(std::max(objlim_, 0)) ||
            half < (n < kMaxSet ? minCube_ : minCube_ / 256.0)) {
            if (n >= kMaxSet)
                throw InputError(prims_[size_t(obj)].loc,
                                 "set overflow in addobject (" + prims_[size_t(obj)].name +
                                     "): more than 511 objects in one octree cube");
            auto& s = t_.sets[si];
            s.insert(std::upper_bound(s.begin(), s.end(), obj), obj);
            return;
        }
        split(cu, node, obj);
    }

    void split(const Cube& cu, Node& node, int32_t obj) {
        std::vector<int32_t> set = std::move(t_.sets[setIndex(node)]);
        t_.sets[setIndex(node)].clear();
        free_.push_back(setIndex(node));
        // Volumes that enclose the whole cube go last in every child, those that cut it
        // after the new object, surfaces first.
        std::vector<int32_t> surfaces, partial, inside;
        for (int32_t o : set) {
            if (!shapes_.isVolume(o))
                surfaces.push_back(o);
            else if (shapes_.overlap(o, cu) == kInside)
                inside.push_back(o);
            else
                partial.push_back(o);
        }
        t_.trees.push_back({kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty, kEmpty});
        const Node tree = Node(t_.trees.size() - 1);
        for (int i = 0; i < 8; ++i) {
            const Cube kc = kidCube(cu, i);
            Node kid = kEmpty;
            for (int32_t o : surfaces) add(kc, kid, o);
            add(kc, kid, obj);
            for (int32_t o : partial) add(kc, kid, o);
            for (int32_t o : inside) add(kc, kid, o);
            t_.trees[size_t(tree)][size_t(i)] = kid;
        }
        node = tree;
    }

    Octree& t_;
    const Shapes& shapes_;
    const std::vector<Primitive>& prims_;
    int objlim_;
    double minCube_;
    std::vector<size_t> free_;  // sets of leaves that split, for reuse
};

}  // namespace

Cube sceneCube(const Shapes& shapes, int32_t first, int32_t end) {
    Vec lo, hi;
    bounds(shapes, first, end, lo, hi);
    Cube cube;
    if (lo[0] > hi[0]) return cube;  // nothing with extent
    for (int i = 0; i < 3; ++i) {
        lo[i] -= kMargin;
        hi[i] += kMargin;
    }
    for (int i = 0; i < 3; ++i)
        if (hi[i] - lo[i] > cube.size) cube.size = hi[i] - lo[i];
    for (int i = 0; i < 3; ++i) cube.org[i] = (hi[i] + lo[i] - cube.size) * .5;
    return cube;
}

bool cubeHolds(const Shapes& shapes, int32_t first, int32_t end, const Cube& cube) {
    Vec lo, hi;
    bounds(shapes, first, end, lo, hi);
    for (int i = 0; i < 3; ++i)
        if (lo[i] < cube.org[i] || hi[i] > cube.org[i] + cube.size) return false;
    return true;
}

void addObjects(Octree& tree, Shapes& shapes, const std::vector<Primitive>& prims, int32_t first,
                int32_t end, const BuildOptions& options) {
    const double minCube = smallestCell(tree.cube.size, options.maxres);
    shapes.setMinCubeSize(minCube);
    Builder b(tree, shapes, prims, options.objlim, minCube);
    for (int32_t i = first; i < end; ++i) b.add(tree.cube, tree.root, i);
    tree.root = b.combine(tree.root);
}

}  // namespace rp::octree
