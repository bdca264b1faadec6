// Decoding RADIANCE's binary object records (see radiance_objects.h). The layout, as
// common/sceneio.c reads it:
//   type names: NUL-terminated strings, ended by an empty one; a record's type is an
//               index into this list
//   records:    type index (1 byte, sign-extended; -1 ends the list)
//               modifier (objsize bytes, relative to the first record, -1 = void)
//               name (string)
//               string argument count (2 bytes), the strings
//               real argument count (2 bytes), the reals (5 bytes each, portio.c)
// RADIANCE is built without IARGS, so there are no integer arguments.
//
// An alias is stored as RADIANCE's getobject() leaves it: with no string argument its
// modifier is the aliased object itself ("inherit", or the alias repeats the target's
// modifier); with one, that argument names the target (the latest modifier of that name
// before the alias) and the modifier is the alias's own. Either way we store a copy of
// the target, renamed, with the alias's modifier in the second case, as our text reader
// does.
#include "scene/radiance_objects.h"

#include <unordered_map>
#include <vector>

#include "scene/portable_reader.h"

namespace rp {

namespace {
// The type index is one signed byte, so no list can usefully be longer.
constexpr size_t kMaxTypes = 127;
}  // namespace

Scene decodeRadianceObjects(std::string_view bytes, size_t& pos, int objsize,
                            const std::string& what) {
    PortableReader r(bytes, pos, what, "binary scene data");
    if (objsize < 1 || objsize > 8) r.fail("object size " + std::to_string(objsize));

    struct TypeEntry {
        std::string name;
        bool known = false;
        PrimType type = PrimType::Polygon;
    };
    std::vector<TypeEntry> types;
    for (std::string name = r.str("the type list"); !name.empty(); name = r.str("the type list")) {
        if (types.size() == kMaxTypes) r.fail("more than " + std::to_string(kMaxTypes) + " types");
        TypeEntry t;
        t.known = primTypeFromName(name, t.type);
        t.name = std::move(name);
        types.push_back(std::move(t));
    }

    Scene scene;
    std::unordered_map<std::string, int32_t> modifiers;  // name -> latest index
    for (;;) {
        const size_t index = scene.prims.size();
        std::string where = "object " + std::to_string(index);
        r.setContext(&where);
        int64_t typeIndex = r.integer(1, "the type");
        if (typeIndex == -1) break;
        if (typeIndex < 0 || static_cast<size_t>(typeIndex) >= types.size())
            r.fail("type index " + std::to_string(typeIndex) + " of " + where + " out of range");
        const TypeEntry& type = types[typeIndex];
        if (!type.known)
            throw InputError(SourceLoc{what, 0},
                             "unknown object type '" + type.name + "' in " + where);

        int64_t mod = r.integer(objsize, "the modifier");
        if (mod != kVoid) {
            if (mod < 0 || static_cast<uint64_t>(mod) >= index)
                r.fail("modifier reference " + std::to_string(mod) + " of " + where +
                       " is not an earlier object");
            if (isSurface(scene.prims[mod].type))
                r.fail(where + " is modified by a surface, " + scene.prims[mod].name);
        }
        Primitive p;
        p.type = type.type;
        p.name = r.str("the name");
        p.loc = SourceLoc{what, 0};
        p.modifier = static_cast<int32_t>(mod);
        p.modifierName = mod == kVoid ? "void" : scene.prims[mod].name;

        const std::string whose = " of " + where + " '" + p.name + "'";
        where += " '" + p.name + "'";
        // Each string needs at least its NUL, each real 5 bytes.
        p.sargs.resize(r.count(2, 1, "string argument count"));
        for (auto& s : p.sargs) s = r.str("a string argument");
        p.rargs.resize(r.count(2, 5, "real argument count"));
        for (auto& v : p.rargs) v = r.real("a real argument");

        if (p.type == PrimType::Alias) {
            if (!p.rargs.empty() || p.sargs.size() > 1) r.fail("alias" + whose + " has arguments");
            int32_t target = p.modifier;
            if (p.sargs.size() == 1) {
                auto it = modifiers.find(p.sargs[0]);
                if (it == modifiers.end())
                    throw InputError(
                        SourceLoc{what, 0},
                        "alias" + whose + " refers to undefined modifier '" + p.sargs[0] + "'");
                target = it->second;
            } else if (target == kVoid) {
                r.fail("alias" + whose + " has no target");
            }
            Primitive copy = scene.prims[target];
            copy.name = p.name;
            copy.loc = p.loc;
            copy.aliasOf = target;
            copy.aliasNamed = p.sargs.size() == 1;
            if (p.sargs.size() == 1) {
                copy.modifier = p.modifier;
                copy.modifierName = p.modifierName;
            }
            p = std::move(copy);
        }
        if (isModifier(p.type)) modifiers[p.name] = static_cast<int32_t>(index);
        scene.prims.push_back(std::move(p));
    }
    r.setContext(nullptr);  // `where` is gone
    return scene;
}

}  // namespace rp
