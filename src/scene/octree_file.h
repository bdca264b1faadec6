// RADIANCE's octree file (FORMAT=Radiance_octree) as RADIANCE's oconv writes it
// (ot/writeoct.c) and reads it back for oconv -i (common/readoct.c): after the header,
// the magic number with the object size (4 bytes here, as in RADIANCE's standard
// build), the cube as four "%.12g" strings, the scene file names ending with an empty
// one (none when frozen), the object count, the tree in pre-order, and for a frozen
// octree the objects as binary scene records (radiance_objects.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/octree_build.h"
#include "scene/primitive.h"

namespace rp {

// The bytes after the header. Non-frozen: `files` are stored and `objects` is null;
// frozen: `objects` (objectCount records) follow the tree and `files` are ignored.
std::string encodeRadianceOctree(const octree::Octree& tree, int64_t objectCount,
                                 const std::vector<std::string>& files, const Scene* objects);

// Header lines (the given ones, then FORMAT=Radiance_octree) and the magic line first.
std::string radianceOctreeHeader(const std::vector<std::string>& lines);

// An octree read back whole: the cube (parsed from its strings, as RADIANCE's atof
// reads them), the scene file names (empty: frozen), the object count, the tree and,
// when frozen, the objects.
struct RadianceOctreeFile {
    octree::Octree tree;
    std::vector<std::string> files;
    int64_t objectCount = 0;
    Scene objects;  // frozen octrees only
};
// Reads the bytes after the header. Every set size, object reference and count is
// checked: a damaged file is an InputError naming `what`, never a crash.
RadianceOctreeFile decodeRadianceOctree(std::string_view binary, const std::string& what);

}  // namespace rp
