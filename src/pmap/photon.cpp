// Photon record helpers: map type names and normal encoding (flux packing: util/colr.h).
#include "pmap/photon.h"

#include <cmath>

namespace rp::pmap {

namespace {
constexpr const char* kTypeNames[kNumPhotonMapTypes] = {
    "Global", "PreComp", "Caustic", "Volume", "Direct", "Contrib", "PreCompContrib"};
}  // namespace

const char* photonMapTypeName(PhotonMapType type) { return kTypeNames[static_cast<int>(type)]; }

std::optional<PhotonMapType> photonMapTypeFromName(std::string_view name) {
    for (int i = 0; i < kNumPhotonMapTypes; ++i)
        if (name == kTypeNames[i]) return static_cast<PhotonMapType>(i);
    return std::nullopt;
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

Vec3 Photon::normal() const {
    Vec3 n{norm[0] / 127.0, norm[1] / 127.0, norm[2] / 127.0};
    const double len = length(n);
    return len > 0 ? n / len : n;
}

}  // namespace rp::pmap
