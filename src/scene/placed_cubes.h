// The cube of the octree or mesh file an instance or mesh record places, as RADIANCE's
// getinstance()/getmeshinst() read it with IO_BOUNDS (the cube stored at the start of the
// file), for the octree builder's and getbbox's bounds (octree_shapes.h). Also the
// cone rewriting getcone() does in the objects themselves.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/octree_shapes.h"
#include "scene/primitive.h"

namespace rp {

// getcone() makes a cone or cup whose radii are equal a cylinder or tube of 7 arguments,
// in the object itself (so a frozen octree stores it so): records [first, end) of scene.
void conesAsRadianceSeesThem(Scene& scene, size_t first);

// Finds placed files on `dirs` (RADIANCE's getpath) and reads each cube once.
class PlacedCubes {
public:
    explicit PlacedCubes(std::vector<std::string> dirs) : dirs_(std::move(dirs)) {}

    // The cube of the file `p` (an instance or mesh) places. Throws InputError at the
    // primitive for a file that is missing or is not an octree (instance) or mesh.
    octree::Cube operator()(const Primitive& p);

private:
    static octree::Cube fileCube(const std::string& path, bool mesh);
    octree::Cube octreeCube(const std::string& path);

    std::vector<std::string> dirs_;
    std::map<std::string, octree::Cube> cubes_;
    std::set<std::string> loading_;
};

}  // namespace rp
