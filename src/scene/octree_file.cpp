// See octree_file.h.
#include "scene/octree_file.h"

#include <cstdio>

#include "scene/portable_reader.h"
#include "scene/radiance_objects.h"
#include "util/portable_io.h"

namespace rp {

namespace {
using namespace octree;

constexpr int kObjSize = 4;             // sizeof(OBJECT) in RADIANCE's standard build
constexpr int kOctMagic = 4 * 8 + 251;  // octree.h OCTMAGIC (MAXOBJSIZ 8)
constexpr size_t kMaxDepth = 64;        // deeper than double precision allows: damage

std::string g12(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.12g", x);
    return buf;
}

// readoct.c gettree(): the pre-order nodes into `t`, sets checked against the count.
Node readNode(PortableReader& r, Octree& t, int objsize, int64_t count, size_t depth) {
    const int kind = r.byte("the octree");
    if (kind == kTreeEmpty) return kEmpty;
    if (kind == kTreeFull) {
        const int64_t n = r.integer(objsize, "an octree object set");
        if (n < 1 || n > int64_t(kMaxSet))
            r.fail("octree object set of " + std::to_string(n) + " objects");
        std::vector<int32_t> set(static_cast<size_t>(n));
        for (auto& o : set) {
            const int64_t ref = r.integer(objsize, "an octree object set");
            if (ref < 0 || ref >= count)
                r.fail("octree object reference " + std::to_string(ref) + " out of range");
            o = int32_t(ref);
        }
        t.sets.push_back(std::move(set));
        return leafNode(t.sets.size() - 1);
    }
    if (kind != kTreeNode) r.fail("octree node of unknown kind " + std::to_string(kind));
    if (depth >= kMaxDepth) r.fail("octree deeper than " + std::to_string(kMaxDepth));
    t.trees.push_back({});
    const Node self = Node(t.trees.size() - 1);
    for (size_t i = 0; i < 8; ++i) {
        const Node kid = readNode(r, t, objsize, count, depth + 1);
        t.trees[size_t(self)][i] = kid;
    }
    return self;
}
}  // namespace

std::string radianceOctreeHeader(const std::vector<std::string>& lines) {
    std::string out = "#?RADIANCE\n";
    for (const std::string& l : lines) out += l + "\n";
    return out + "FORMAT=Radiance_octree\n\n";
}

std::string encodeRadianceOctree(const Octree& tree, int64_t objectCount,
                                 const std::vector<std::string>& files, const Scene* objects) {
    using namespace portable;
    std::string out;
    putInt(out, kOctMagic + kObjSize, 2);
    for (double c : tree.cube.org) putStr(out, g12(c));
    putStr(out, g12(tree.cube.size));
    if (!objects)
        for (const std::string& f : files) putStr(out, f);
    putStr(out, "");
    putInt(out, objectCount, kObjSize);
    putOctreeNodes(out, tree, kObjSize);
    if (objects) encodeRadianceObjects(*objects, kObjSize, out);
    return out;
}

RadianceOctreeFile decodeRadianceOctree(std::string_view bin, const std::string& what) {
    size_t pos = 0;
    PortableReader r(bin, pos, what, "octree");
    const int64_t objsize = r.integer(2, "the magic number") - kOctMagic;
    if (objsize <= 0 || objsize > 8)
        throw InputError(SourceLoc{what, 0}, "incompatible octree format");
    RadianceOctreeFile f;
    readRadianceCube(r, f.tree.cube.org, f.tree.cube.size);
    for (std::string name = r.str("the scene file names"); !name.empty();
         name = r.str("the scene file names"))
        f.files.push_back(std::move(name));
    f.objectCount = r.integer(int(objsize), "the object count");
    if (f.objectCount < 0 || f.objectCount > INT32_MAX)
        r.fail("object count " + std::to_string(f.objectCount));
    f.tree.root = readNode(r, f.tree, int(objsize), f.objectCount, 0);
    if (f.files.empty()) {
        f.objects = decodeRadianceObjects(bin, pos, int(objsize), what);
        if (int64_t(f.objects.prims.size()) != f.objectCount)
            r.fail(std::to_string(f.objects.prims.size()) + " objects, the octree says " +
                   std::to_string(f.objectCount));
    }
    return f;
}

}  // namespace rp
