// What the rest of the program needs to know about a material type without its
// arguments, one row per RADIANCE material type (ray.html) in one place: the source
// list, the pretest, previews, rvu's picking and antimatter tables read these rather
// than testing types themselves. Arguments' consequences are MaterialRecord's.
#pragma once

#include <cstdint>

#include "scene/primitive.h"

namespace rp::material {

struct TypeTraits {
    enum class Light : uint8_t { None, Light, Illum, Glow, Spotlight };
    // Planar surfaces of these relay sources as virtual sources (virtuals.c).
    enum class Relay : uint8_t { None, Mirror, Prism1, Prism2 };
    // How a quick preview (rpreview) colours it: grey, its first three arguments, or
    // those scaled to a white-ish colour of the same balance.
    enum class Preview : uint8_t { Grey, Reflectance, Emitter };

    bool material = false;  // a material type at all
    Light light = Light::None;
    Relay relay = Relay::None;
    Preview preview = Preview::Grey;
    bool antimatter = false;
    bool mist = false;
    // The -dp pretest's rays stop at it: opaque whatever its arguments (the pretest has
    // no material calculation; transmitting, emitting and unknown kinds let it pass).
    bool opaqueToPretest = false;
};

// The row of `t` (a default row, `material` false, for non-material types).
TypeTraits typeTraits(PrimType t);

}  // namespace rp::material
