// The writer half of radiance_objects.h: RADIANCE's binary scene records as
// common/sceneio.c lays them out (type-name table, then one record per object).
#include <array>
#include <string_view>

#include "scene/radiance_objects.h"
#include "util/error.h"
#include "util/portable_io.h"

namespace rp {
namespace {

// RADIANCE 5.x's object type table (otypes.h), in its order: a record stores its type as
// an index into this list, and the file carries the list so readers can remap it.
constexpr std::array<std::string_view, 53> kTypeNames = {
    "polygon",    "cone",      "sphere",     "texfunc",    "ring",       "cylinder",  "instance",
    "cup",        "bubble",    "tube",       "mesh",       "alias",      "plastic",   "metal",
    "glass",      "trans",     "dielectric", "plastic2",   "metal2",     "trans2",    "interface",
    "plasfunc",   "metfunc",   "brightfunc", "brightdata", "brighttext", "colorpict", "glow",
    "source",     "light",     "illum",      "spotlight",  "mist",       "mirror",    "transfunc",
    "BRTDfunc",   "BSDF",      "aBSDF",      "plasdata",   "metdata",    "transdata", "colorfunc",
    "antimatter", "colordata", "colortext",  "texdata",    "mixfunc",    "mixdata",   "mixtext",
    "mixpict",    "prism1",    "prism2",     "ashik2"};

int typeIndex(const Primitive& p) {
    std::string_view name = primTypeName(p.type);
    for (size_t i = 0; i < kTypeNames.size(); ++i)
        if (kTypeNames[i] == name) return static_cast<int>(i);
    throw InputError(
        p.loc, "type '" + std::string(name) + "' has no code in RADIANCE's binary scene format");
}

constexpr int kAliasType = 11;  // "alias" in kTypeNames

// An alias as readobj.c getobject() leaves it: its modifier is the aliased object, or
// (when it has a modifier of its own) that modifier and the aliased name as its one
// string argument.
void putAlias(std::string& out, const Scene& scene, const Primitive& p, int objsize) {
    using namespace portable;
    putInt(out, kAliasType, 1);
    putInt(out, p.aliasNamed ? p.modifier : p.aliasOf, objsize);
    putStr(out, p.name);
    putInt(out, p.aliasNamed ? 1 : 0, 2);
    if (p.aliasNamed) putStr(out, scene.prims[static_cast<size_t>(p.aliasOf)].name);
    putInt(out, 0, 2);
}

}  // namespace

void encodeRadianceObjects(const Scene& scene, int objsize, std::string& out) {
    using namespace portable;
    RP_CHECK(objsize >= 1 && objsize <= 8);
    for (std::string_view name : kTypeNames) putStr(out, name);
    putStr(out, "");
    for (const Primitive& p : scene.prims) {
        // Integer arguments exist only in RADIANCE builds with IARGS, which the
        // standard build (and its readers) leave out.
        if (!p.iargs.empty())
            throw InputError(p.loc, "integer arguments cannot be stored in a binary scene");
        if (p.aliasOf >= 0) {
            putAlias(out, scene, p, objsize);
            continue;
        }
        putInt(out, typeIndex(p), 1);
        putInt(out, p.modifier, objsize);
        putStr(out, p.name);
        putInt(out, static_cast<int64_t>(p.sargs.size()), 2);
        for (const std::string& s : p.sargs) putStr(out, s);
        putInt(out, static_cast<int64_t>(p.rargs.size()), 2);
        for (double r : p.rargs) putFlt(out, r);
    }
    putInt(out, -1, 1);  // end mark
}

}  // namespace rp
