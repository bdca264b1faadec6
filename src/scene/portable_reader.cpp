// The octree skipper shared by the octree and mesh readers (see portable_reader.h).
#include "scene/portable_reader.h"

#include <cerrno>
#include <cstdlib>
#include <vector>

namespace rp {

void skipRadianceTree(PortableReader& r, int objsize, int64_t maxRef) {
    // RADIANCE's object.h MAXSET: the largest object set a full node holds.
    constexpr int64_t kMaxSet = 511;
    // Far deeper than any octree (each level halves the cube: 64 levels is beyond
    // double precision), so only a damaged file reaches it.
    constexpr size_t kMaxDepth = 64;
    // Children still to read at each open level; the root is one pending node.
    std::vector<int> pending{1};
    while (!pending.empty()) {
        if (pending.back() == 0) {
            pending.pop_back();
            continue;
        }
        --pending.back();
        int kind = r.byte("the octree");
        if (kind == 0) continue;  // empty
        if (kind == 1) {          // full: an object set
            int64_t n = r.integer(objsize, "an octree object set");
            if (n < 0 || n > kMaxSet)
                r.fail("octree object set of " + std::to_string(n) + " objects");
            for (int64_t i = 0; i < n; ++i) {
                int64_t ref = r.integer(objsize, "an octree object set");
                if (ref < 0 || ref >= maxRef)
                    r.fail("octree object reference " + std::to_string(ref) + " out of range");
            }
        } else if (kind == 2) {  // tree: eight children follow
            if (pending.size() >= kMaxDepth)
                r.fail("octree deeper than " + std::to_string(kMaxDepth));
            pending.push_back(8);
        } else {
            r.fail("octree node of unknown kind " + std::to_string(kind));
        }
    }
}

std::array<std::string, 4> readRadianceCube(PortableReader& r, std::array<double, 3>& origin,
                                            double& size) {
    std::array<std::string, 4> text;
    static const char* const kWhat[4] = {"the cube origin x", "the cube origin y",
                                         "the cube origin z", "the cube size"};
    for (int i = 0; i < 4; ++i) {
        text[i] = r.str(kWhat[i]);
        const char* s = text[i].c_str();
        char* end = nullptr;
        errno = 0;
        double v = std::strtod(s, &end);
        if (end == s || *end != '\0' || errno == ERANGE || !std::isfinite(v))
            r.fail(std::string(kWhat[i]) + " '" + text[i] + "' is not a number");
        if (i < 3)
            origin[i] = v;
        else
            size = v;
    }
    return text;
}

}  // namespace rp
