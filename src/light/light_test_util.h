// Test-only helpers for light/ tests: build Scene records in code (materials with
// their real arguments, surfaces) and simple statistics. Not part of rp_light.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "scene/primitive.h"

namespace rp::light::testing {

class Builder {
public:
    int32_t add(PrimType type, const std::string& name, std::vector<double> rargs,
                int32_t modifier = kVoid, std::vector<std::string> sargs = {}) {
        Primitive p;
        p.type = type;
        p.name = name;
        p.modifier = modifier;
        p.modifierName = modifier == kVoid ? "void" : scene_.prims[size_t(modifier)].name;
        p.rargs = std::move(rargs);
        p.sargs = std::move(sargs);
        p.loc = {"test.rad", int(scene_.prims.size()) + 1};
        scene_.prims.push_back(std::move(p));
        return int32_t(scene_.prims.size() - 1);
    }
    int32_t light(const std::string& name, double r, double g, double b, int32_t mod = kVoid) {
        return add(PrimType::Light, name, {r, g, b}, mod);
    }
    // Axis-aligned square [x0,x1]x[y0,y1] at height z, facing +z (or -z if down).
    int32_t squareZ(int32_t mat, double x0, double x1, double y0, double y1, double z,
                    bool down = false, const std::string& name = "sq") {
        std::vector<double> v = {x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z};
        if (down) v = {x0, y0, z, x0, y1, z, x1, y1, z, x1, y0, z};
        return add(PrimType::Polygon, name, v, mat);
    }
    const Scene& scene() const { return scene_; }

private:
    Scene scene_;
};

// Mean and standard error of a running sample.
struct Stats {
    double sum = 0, sum2 = 0;
    long n = 0;
    void add(double x) {
        sum += x;
        sum2 += x * x;
        ++n;
    }
    double mean() const { return sum / double(n); }
    double sigmaOfMean() const {
        double m = mean();
        return std::sqrt(std::fmax(0.0, sum2 / double(n) - m * m) / double(n));
    }
};

}  // namespace rp::light::testing
