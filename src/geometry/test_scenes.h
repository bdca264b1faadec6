// Test-only helpers: build Scene records programmatically (no reader needed). Included
// by the *_test.cpp files of this folder only.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/primitive.h"

namespace rp::testing {

class SceneBuilder {
public:
    // Adds a modifier record (a plastic, say) and returns its index.
    int32_t material(const std::string& name, PrimType type = PrimType::Plastic) {
        Primitive p;
        p.type = type;
        p.name = name;
        p.rargs = {0.5, 0.5, 0.5, 0, 0};
        return add(std::move(p));
    }
    // Adds a surface with the given real arguments; returns its index.
    int32_t surface(PrimType type, std::vector<double> rargs, int32_t modifier = kVoid,
                    const std::string& name = "") {
        Primitive p;
        p.type = type;
        p.name = name.empty() ? "s" + std::to_string(scene_.prims.size()) : name;
        p.modifier = modifier;
        p.modifierName = modifier == kVoid ? "void" : scene_.prims[modifier].name;
        p.rargs = std::move(rargs);
        p.loc = {"test.rad", int(scene_.prims.size()) + 1};
        return add(std::move(p));
    }
    const Scene& scene() const { return scene_; }

private:
    int32_t add(Primitive p) {
        scene_.prims.push_back(std::move(p));
        return int32_t(scene_.prims.size() - 1);
    }
    Scene scene_;
};

}  // namespace rp::testing
