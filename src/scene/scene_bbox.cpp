// See scene_bbox.h.
#include "scene/scene_bbox.h"

#include <cstdio>
#include <string_view>

#include "calc/search_path.h"
#include "scene/octree_shapes.h"
#include "scene/placed_cubes.h"
#include "scene/scene_file.h"
#include "util/error.h"
#include "util/file_read.h"
#include "util/header.h"
#include "util/paths.h"

namespace rp {

BoundingBox sceneBoundingBox(const std::vector<std::string>& inputs, const LoadOptions& options,
                             const std::vector<std::string>& searchPath) {
    LoadOptions o = options;
    o.radianceNumbering = true;  // keep what RADIANCE keeps (polygons without area count)
    o.geometryOnly = true;       // materials may be in other files (rad: getbbox of its scene)
    SceneReader reader(o);
    for (const std::string& f : inputs) {
        if (f == "-" || f[0] == '!') {
            reader.readFile(f);
            continue;
        }
        const std::string bytes = readFileBytes(f);
        Header header;
        std::string_view rest;
        if (splitHeader(bytes, header, rest))
            throw InputError(SourceLoc{f, 0},
                             "not a scene description (FORMAT=" + header.format() + ")");
        if (bytes.find('\0') != std::string::npos)
            throw InputError(SourceLoc{f, 0}, "binary data, not a scene description");
        reader.readContents(f, bytes);
    }
    Scene scene = reader.take();
    conesAsRadianceSeesThem(scene, 0);
    PlacedCubes cubes(searchPath.empty() ? calc::defaultSearchPath(projectLibDir()) : searchPath);
    const octree::Shapes shapes(scene, scene.prims.size(),
                                [&cubes](const Primitive& p) { return cubes(p); });
    BoundingBox box;
    for (size_t i = 0; i < scene.prims.size(); ++i) shapes.addBounds(int32_t(i), box.min, box.max);
    return box;
}

std::string formatBoundingBox(const BoundingBox& box, bool header) {
    std::string out;
    if (header) out = "     xmin      xmax      ymin      ymax      zmin      zmax\n";
    char buf[128];
    std::snprintf(buf, sizeof buf, "%9g %9g %9g %9g %9g %9g\n", box.min[0], box.max[0], box.min[1],
                  box.max[1], box.min[2], box.max[2]);
    return out + buf;
}

}  // namespace rp
