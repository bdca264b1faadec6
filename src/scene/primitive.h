// The parsed form of a RADIANCE scene: plain records, one per primitive or modifier,
// in input order, each with its SourceLoc. Nothing here knows about rendering;
// materials, lights and accelerator geometry are built from these records later.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace rp {

// Every primitive type of the RADIANCE reference manual (ray.html).
enum class PrimType : uint8_t {
    // surfaces
    Source,
    Sphere,
    Bubble,
    Polygon,
    Cone,
    Cup,
    Cylinder,
    Tube,
    Ring,
    Instance,
    Mesh,
    // light-emitting materials
    Light,
    Illum,
    Glow,
    Spotlight,
    // reflecting/refracting materials
    Mirror,
    Prism1,
    Prism2,
    Plastic,
    Metal,
    Trans,
    Plastic2,
    Metal2,
    Trans2,
    Ashik2,
    Mist,
    Dielectric,
    Interface,
    Glass,
    Plasfunc,
    Metfunc,
    Transfunc,
    BRTDfunc,
    Plasdata,
    Metdata,
    Transdata,
    BSDF,
    ABSDF,
    WGMDfunc,
    Antimatter,
    // textures
    Texfunc,
    Texdata,
    // patterns
    Colorfunc,
    Brightfunc,
    Colordata,
    Brightdata,
    Colorpict,
    Colortext,
    Brighttext,
    Spectrum,
    Specfile,
    Specfunc,
    Specdata,
    Specpict,
    // mixtures
    Mixfunc,
    Mixdata,
    Mixpict,
    Mixtext,
    // alias (resolved by the reader: never appears in a Scene)
    Alias,
};

enum class PrimCategory : uint8_t { Surface, Material, Texture, Pattern, Mixture, Alias };

// RADIANCE spelling ("polygon", "BRTDfunc", ...).
std::string_view primTypeName(PrimType t);
// Looks a RADIANCE type name up; false if unknown.
bool primTypeFromName(std::string_view name, PrimType& out);
PrimCategory primCategory(PrimType t);
inline bool isSurface(PrimType t) { return primCategory(t) == PrimCategory::Surface; }
inline bool isModifier(PrimType t) { return !isSurface(t); }

constexpr int32_t kVoid = -1;  // modifier index of "void"

struct Primitive {
    PrimType type = PrimType::Polygon;
    std::string name;
    std::string modifierName;        // as written ("void" for none)
    int32_t modifier = kVoid;        // index into Scene::prims of the resolved modifier
    std::vector<std::string> sargs;  // string arguments
    std::vector<long> iargs;         // integer arguments
    std::vector<double> rargs;       // real arguments
    SourceLoc loc;                   // where it was defined
    // Set by attachObjects (scene_load.h): the Scene::objects entry this record belongs
    // to (-1: the scene itself), and for instance and mesh primitives the object placed.
    int32_t object = -1;
    int32_t placed = -1;
    // RADIANCE keeps an alias as an object of its own, which its binary scene records
    // (oconv -f) store as such; we keep a copy of the aliased record instead. For a
    // copy made from an alias: the aliased record's index, and whether RADIANCE names
    // it in a string argument (the alias has a modifier of its own) rather than making
    // it the alias's modifier ("inherit", or the same modifier as the aliased record).
    int32_t aliasOf = -1;
    bool aliasNamed = false;
};

struct MeshData;

// An octree or mesh file that instance and mesh primitives place, loaded once however
// often it is placed. Its records follow the scene's own in Scene::prims, modifier
// indices resolved within them: an octree's surfaces and modifiers, a mesh's materials.
struct SceneObject {
    enum class Kind : uint8_t { Octree, Mesh };
    Kind kind = Kind::Octree;
    std::string path;                      // as found on the search path
    int32_t firstPrim = 0, endPrim = 0;    // its records in Scene::prims
    std::shared_ptr<const MeshData> mesh;  // Kind::Mesh: the triangles
};

// A file the scene was read from, for the photon map stale check.
struct SceneInput {
    std::string path;
    int64_t mtime = 0;  // seconds since the epoch; 0 if unknown (stdin, command output)
};

struct Scene {
    std::vector<Primitive> prims;      // surfaces and modifiers in input order
    std::vector<SceneInput> inputs;    // files read, in order
    std::vector<SceneObject> objects;  // what instances and meshes place (attachObjects)

    // The scene's own records come first, then the objects'.
    int32_t ownCount() const {
        return objects.empty() ? int32_t(prims.size()) : objects.front().firstPrim;
    }
};

// RADIANCE findmaterial (initotypes.c): the first material on the modifier chain that
// starts at `modifier`, past patterns, textures and aliases, or the mixture that ends it;
// kVoid if the chain ends in void. The one walk every module uses.
int32_t chainMaterial(const Scene& scene, int32_t modifier);

// RADIANCE's transparent materials (initotypes.c T_TRANSP): trans, trans2, dielectric,
// interface, mist, glass and aBSDF. Between coincident surfaces an opaque one wins.
bool isTransparentMaterial(PrimType t);

}  // namespace rp
