// A triangle mesh as RADIANCE's compiled mesh files (.rtm, FORMAT=Radiance_tmesh, written
// by obj2mesh) hold it, decoded into flat arrays: what the mesh reader (mesh_file.h)
// returns, what obj2mesh writes from, and what the accelerator places. Positions are
// floats laid out as Embree's shared vertex buffer wants them, so a mesh is kept in
// memory once: RADIANCE quantises positions to 32 bits within the mesh cube, and floats
// (24 bits relative) are within a few micrometres of that for building-sized meshes.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/primitive.h"

namespace rp {

struct MeshData {
    // Vertex flags per vertex (RADIANCE mesh.h MT_N, MT_UV): which optional values it has.
    static constexpr uint8_t kHasNormal = 2;
    static constexpr uint8_t kHasUV = 4;

    std::string path;  // the file it was read from (errors, the photon map stale check)

    // The mesh cube (RADIANCE mcube: origin corner and side) and (u, v) limits as stored.
    std::array<double, 3> cubeOrigin{};
    double cubeSize = 0;
    std::array<std::array<double, 2>, 2> uvLimits{};  // [0] = (umin, vmin), [1] = (umax, vmax)

    // 3 floats per vertex (x, y, z), plus one unused float at the end: Embree reads the
    // last vertex with a 16-byte load.
    std::vector<float> positions;
    // Per vertex, empty when no vertex has one; unit vectors (zero where absent).
    std::vector<std::array<float, 3>> normals;
    // Per vertex, empty when no vertex has them (zero where absent).
    std::vector<std::array<float, 2>> uvs;
    // Per vertex, empty when no vertex has a normal or (u, v): kHasNormal | kHasUV bits.
    std::vector<uint8_t> vertexFlags;

    // 3 vertex indices per triangle, counter-clockwise seen from the front (RADIANCE's
    // normal is (v1 - v0) x (v2 - v0)).
    std::vector<uint32_t> triangles;
    // Per triangle, an index into `materials.prims` of the modifier that the mesh gives
    // it, or kVoid; empty when every triangle has `soleMaterial`.
    std::vector<int32_t> triangleMaterial;
    int32_t soleMaterial = kVoid;
    // The mesh's own modifiers (obj2mesh -a/-l material files), in file order, with
    // modifier indices into this list (Primitive::modifier) as in any Scene.
    Scene materials;

    size_t vertexCount() const { return positions.size() / 3; }
    size_t triangleCount() const { return triangles.size() / 3; }
    int32_t materialOf(size_t triangle) const {
        return triangleMaterial.empty() ? soleMaterial : triangleMaterial[triangle];
    }
    uint8_t flagsOf(size_t vertex) const { return vertexFlags.empty() ? 0 : vertexFlags[vertex]; }
};

}  // namespace rp
