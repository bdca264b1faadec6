// The photon record and photon map kinds, laid out as RADIANCE's `Photon` (pmapdata.h) so
// that what we hold in memory is byte for byte what a RADIANCE "3.1k" map file stores.
// Search structures live in kdtree.h, the map with its statistics and files in photon_map.h.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "util/colr.h"
#include "util/vec.h"

namespace rp::pmap {

// RADIANCE's photon map types, in RADIANCE's order (pmaptype.h), which the option letters
// -apg, -app, -apc, -apv, -apd, -apC of mkpmap select; then the precomputed contribution
// map of the photon-map development branch (mkpmap -apC with -m/-M; precomp_contrib.h),
// whose photons' `primary` is the index of their coefficient records.
enum class PhotonMapType : uint8_t {
    Global,
    PreComp,
    Caustic,
    Volume,
    Direct,
    Contrib,
    PreCompContrib
};
constexpr int kNumPhotonMapTypes = 7;

// "Global", "PreComp", "Caustic", "Volume", "Direct", "Contrib" (RADIANCE's pmapName).
const char* photonMapTypeName(PhotonMapType type);
// Inverse of photonMapTypeName (exact, case-sensitive); nullopt for anything else.
std::optional<PhotonMapType> photonMapTypeFromName(std::string_view name);

// Flux is stored as RADIANCE's packed RGBE (util/colr.h: toColr / colrToRgb).

// One stored photon: 24 bytes, the layout of RADIANCE's default build (RGBE flux, kd-tree).
// The flag byte uses GCC's bitfield order for RADIANCE's `discr:2, caustic:1, proc:5`:
// bits 0-1 split axis of the kd-tree node, bit 2 caustic, bits 3-7 RADIANCE's forking
// subprocess index (we never set it, but keep whatever a file holds so round trips are
// lossless).
struct Photon {
    float pos[3] = {0, 0, 0};
    int8_t norm[3] = {0, 0, 0};  // surface normal x 127 (incident direction for volume photons)
    uint8_t flags = 0;
    Colr flux = {0, 0, 0, 0};
    uint32_t primary = 0;  // index into the map's primaries (contrib maps); 0 otherwise

    static constexpr uint8_t kDiscrMask = 0x03;
    static constexpr uint8_t kCausticBit = 0x04;
    static constexpr int kProcShift = 3;

    int discr() const { return flags & kDiscrMask; }
    void setDiscr(int axis) { flags = static_cast<uint8_t>((flags & ~kDiscrMask) | (axis & 3)); }
    bool caustic() const { return (flags & kCausticBit) != 0; }
    void setCaustic(bool c) {
        flags = static_cast<uint8_t>(c ? (flags | kCausticBit) : (flags & ~kCausticBit));
    }
    int proc() const { return flags >> kProcShift; }

    Vec3 position() const { return {pos[0], pos[1], pos[2]}; }
    // Decoded flux in watts, as RADIANCE's getPhotonFlux.
    std::array<float, 3> fluxRgb() const { return colrToRgb(flux); }
    void setFlux(double r, double g, double b) { flux = toColr(r, g, b); }
    // RADIANCE compat: newPhoton() stores 127.0 * n[i] truncated toward zero.
    void setNormal(const Vec3& n);
    // The stored normal, renormalised (zero stays zero).
    Vec3 normal() const;

    bool operator==(const Photon& o) const = default;
};
static_assert(sizeof(Photon) == 24, "photon record must stay at RADIANCE's 24 bytes");

// Convenience for emitters and tests: a photon at `p` with normal `n` (unit), flux `rgb`.
Photon makePhoton(const Vec3& p, const Vec3& n, const std::array<double, 3>& rgb,
                  bool caustic = false, uint32_t primary = 0);

// A primary ray of a contribution photon map: the emitting source's index (RADIANCE's
// default build, file version 3.1k).
struct PhotonPrimary {
    int16_t srcIdx = -1;
    bool operator==(const PhotonPrimary& o) const = default;
};

// Where a primary left its source, kept by maps of RADIANCE's 3.1kPD variant (its
// PMAP_CBDM build; mkpmap -apCPD): the emission point and the direction back toward the
// source (the reverse of the emitted one) as a util/dir_code.h code, so that rcontrib can
// bin photon contributions by where they came from.
struct PrimaryRay {
    std::array<float, 3> pos{};
    int32_t dir = 0;
    bool operator==(const PrimaryRay& o) const = default;
};

}  // namespace rp::pmap
