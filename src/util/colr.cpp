#include "util/colr.h"

#include <cmath>

#include "util/fast_frexp.h"

namespace rp {

namespace {
constexpr int kColrExcess = 128;  // COLXS in color.h
}

Colr toColr(double r, double g, double b) {
    if (std::isnan(r)) r = 0;
    if (std::isnan(g)) g = 0;
    if (std::isnan(b)) b = 0;
    double d = std::fmax(r, std::fmax(g, b));
    if (d <= 1e-32) return {0, 0, 0, 0};
    if (!std::isfinite(d)) return {255, 255, 255, 255};
    int e = 0;
    double scale = frexpFast(d, e) * 256.0 / d;
    if (e + kColrExcess > 255) return {255, 255, 255, 255};
    if (e + kColrExcess < 1) return {0, 0, 0, 0};  // below the smallest exponent
    auto mant = [scale](double v) -> uint8_t {
        return v > 0 ? static_cast<uint8_t>(static_cast<int>(v * scale)) : 0;
    };
    return {mant(r), mant(g), mant(b), static_cast<uint8_t>(e + kColrExcess)};
}

}  // namespace rp
