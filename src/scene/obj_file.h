// Wavefront .OBJ geometry as RADIANCE's obj2mesh reads it (ot/wfconv.c): v, vt, vn and
// f statements (v, v/vt, v//vn, v/vt/vn, negative indices counting back from the last
// vertex), usemtl and g for the material of later faces, o and usemap accepted, other
// statements counted and reported in one warning. Faces of more than three vertices
// are split as RADIANCE splits them (ear clipping in the plane of the face's dominant
// axis, common/triangulate.c), which is not a fan from the first vertex.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/mesh_data.h"
#include "scene/mesh_write.h"

namespace rp {

struct ObjMesh {
    // Triangles in file order, in double precision as the file gives them; materials
    // are not yet resolved (MeshTriangleInput::material is kVoid, loc is the face line).
    std::vector<MeshTriangleInput> triangles;
    // Per triangle, the material name RADIANCE would look up: the last usemtl name, or
    // if none the last group name (g), or "" (void); "void" also means void.
    std::vector<std::string> materialNames;
    int statements = 0;
    int unrecognised = 0;  // statements RADIANCE's obj2mesh does not know
};

// Parses OBJ text; `file` names the input in errors. Malformed numbers, bad or
// out-of-range vertex references and faces with fewer than three vertices are
// InputErrors at the statement's line. Warns "N of M statements unrecognized".
ObjMesh parseObj(std::string_view text, const std::string& file);

// Gives each triangle its material: kVoid when `materials` is empty (obj2mesh without
// -a/-l) or the name is "" or "void", else the latest modifier of that name in
// `materials`; a name with no such modifier is an InputError at the face's line.
void assignObjMaterials(ObjMesh& obj, const Scene& materials);

// The triangles as indexed mesh data: vertices that share position, normal and (u, v)
// are merged; positions are rounded to float.
MeshData objToMeshData(const ObjMesh& obj, const Scene& materials);

}  // namespace rp
