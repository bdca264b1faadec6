// Photon record helpers: map type names, RGBE flux packing, normal encoding.
#include "pmap/photon.h"

#include <cmath>

namespace rp::pmap {

namespace {
constexpr const char* kTypeNames[kNumPhotonMapTypes] = {"Global", "PreComp", "Caustic",
                                                        "Volume", "Direct",  "Contrib"};
constexpr int kColrExcess = 128;
}  // namespace

const char* photonMapTypeName(PhotonMapType type) { return kTypeNames[static_cast<int>(type)]; }

std::optional<PhotonMapType> photonMapTypeFromName(std::string_view name) {
    for (int i = 0; i < kNumPhotonMapTypes; ++i)
        if (name == kTypeNames[i]) return static_cast<PhotonMapType>(i);
    return std::nullopt;
}

Colr fluxToColr(double r, double g, double b) {
    if (std::isnan(r)) r = 0;
    if (std::isnan(g)) g = 0;
    if (std::isnan(b)) b = 0;
    double d = std::fmax(r, std::fmax(g, b));
    if (d <= 1e-32) return {0, 0, 0, 0};
    if (!std::isfinite(d)) return {255, 255, 255, 255};
    int e = 0;
    double scale = std::frexp(d, &e) * 256.0 / d;
    if (e + kColrExcess > 255) return {255, 255, 255, 255};
    if (e + kColrExcess < 1) return {0, 0, 0, 0};  // below the smallest exponent
    auto mant = [scale](double v) -> uint8_t {
        return v > 0 ? static_cast<uint8_t>(static_cast<int>(v * scale)) : 0;
    };
    return {mant(r), mant(g), mant(b), static_cast<uint8_t>(e + kColrExcess)};
}

std::array<float, 3> colrToFlux(const Colr& c) {
    if (c[3] == 0) return {0, 0, 0};
    double f = std::ldexp(1.0, static_cast<int>(c[3]) - (kColrExcess + 8));
    return {static_cast<float>((c[0] + 0.5) * f), static_cast<float>((c[1] + 0.5) * f),
            static_cast<float>((c[2] + 0.5) * f)};
}

void Photon::setNormal(const Vec3& n) {
    for (int i = 0; i < 3; ++i) {
        double v = 127.0 * std::fmax(-1.0, std::fmin(1.0, n[i]));
        norm[i] = static_cast<int8_t>(v);  // truncation, as the C assignment in newPhoton()
    }
}

Photon makePhoton(const Vec3& p, const Vec3& n, const std::array<double, 3>& rgb, bool caustic,
                  uint32_t primary) {
    Photon ph;
    ph.pos[0] = static_cast<float>(p.x);
    ph.pos[1] = static_cast<float>(p.y);
    ph.pos[2] = static_cast<float>(p.z);
    ph.setNormal(n);
    ph.setFlux(rgb[0], rgb[1], rgb[2]);
    ph.setCaustic(caustic);
    ph.primary = primary;
    return ph;
}

}  // namespace rp::pmap
