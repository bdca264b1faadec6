// RGB colour for radiometric quantities (radiance, irradiance, flux, reflectance) in
// double precision. Pictures store float pixels (image/rgbe.h); photons store RGBE.
#pragma once

#include <algorithm>

namespace rp {

struct Color {
    double r = 0, g = 0, b = 0;

    constexpr Color() = default;
    constexpr Color(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    static constexpr Color grey(double v) { return {v, v, v}; }

    constexpr double operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    constexpr double& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
    constexpr Color operator+(const Color& o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Color operator-(const Color& o) const { return {r - o.r, g - o.g, b - o.b}; }
    constexpr Color operator*(const Color& o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Color operator*(double s) const { return {r * s, g * s, b * s}; }
    constexpr Color operator/(double s) const { return {r / s, g / s, b / s}; }
    constexpr Color& operator+=(const Color& o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    constexpr Color& operator*=(const Color& o) {
        r *= o.r;
        g *= o.g;
        b *= o.b;
        return *this;
    }
    constexpr Color& operator*=(double s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    constexpr bool operator==(const Color&) const = default;

    constexpr bool isBlack() const { return r <= 0 && g <= 0 && b <= 0; }
    constexpr double max() const { return std::max({r, g, b}); }
    constexpr double min() const { return std::min({r, g, b}); }
    constexpr double average() const { return (r + g + b) / 3; }
    // RADIANCE's bright(): luminance-like weighting of its standard RGB primaries
    // (color.h: CIE_rf 0.265, CIE_gf 0.670, CIE_bf 0.065). The validation references
    // use the same weights.
    constexpr double brightness() const { return 0.265 * r + 0.670 * g + 0.065 * b; }
};

constexpr Color operator*(double s, const Color& c) { return c * s; }

}  // namespace rp
