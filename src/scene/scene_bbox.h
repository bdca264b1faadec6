// getbbox, RADIANCE's scene bounding box (getbbox(1), ot/getbbox.c): the axis-aligned
// box around every surface of some scene descriptions, grown object by object as
// RADIANCE's add2bbox grows it (octree_shapes.h), so instances and meshes count by their
// file's cube through their transform. Options live in tools/getbbox.cpp.
#pragma once

#include <string>
#include <vector>

#include "scene/radiance_geom.h"
#include "scene/reader.h"

namespace rp {

// Starts empty as RADIANCE's does: min at FHUGE, max at -FHUGE.
struct BoundingBox {
    radgeom::Vec min{radgeom::kHuge, radgeom::kHuge, radgeom::kHuge};
    radgeom::Vec max{-radgeom::kHuge, -radgeom::kHuge, -radgeom::kHuge};
};

// The box of the scene descriptions `inputs` (files, "-" for standard input, "!command"),
// read in order as oconv reads them; instances' octrees and meshes are found on
// `searchPath` (empty: RAYPATH or "." and the project's library). Throws InputError for
// input that is not a scene description (an octree, a picture), bad records, and placed
// files that are missing or not octrees or meshes.
BoundingBox sceneBoundingBox(const std::vector<std::string>& inputs, const LoadOptions& options,
                             const std::vector<std::string>& searchPath = {});

// RADIANCE's output: the "     xmin      xmax ..." line (unless !header), then the six
// numbers in "%9g" (xmin xmax ymin ymax zmin zmax), each line ending in a newline.
std::string formatBoundingBox(const BoundingBox& box, bool header);

}  // namespace rp
