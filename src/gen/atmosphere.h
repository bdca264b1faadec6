// A precomputed spectral atmosphere for genssky (RADIANCE 6's spectral sky): Rayleigh,
// Mie and ozone over a spherical earth, every order of scattering and the ground's
// reflection, in 20 bands of 20 nm from 380 to 780 nm. The method is Bruneton and
// Neyret's precomputed atmospheric scattering (2008; the 2017 reference formulation):
// tables of the transmittance to the top of the atmosphere, of the light scattered
// along every ray (by view zenith, sun zenith and view-sun angle, at every height) and of
// the ground's indirect irradiance, built order by order. Grid points here lie exactly
// on the tables' parametrisation (a lookup at a grid point returns what was computed
// there). Generating the sky itself (pictures, the sun, clouds) is genssky.h's job.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "calc/data_file.h"
#include "util/vec.h"

namespace rp::gen::atmos {

constexpr int kBands = 20;
constexpr double kShortestNm = 380, kLongestNm = 780, kBandNm = 20;
// Per band, shortest wavelength (centre 390 nm) first.
using Spectrum = std::array<double, kBands>;

constexpr double kGroundRadius = 6360e3;  // m
constexpr double kTopRadius = 6420e3;     // m: 60 km of atmosphere
constexpr double kMinSunCosine = -0.2;    // the tables' lowest sun (twilight)
constexpr double kSunAngularRadius = 0.004625;
constexpr double kSunSolidAngle = 6.7967e-5;  // sr, a 0.533 degree disc
constexpr double kMieEccentricity = 0.7;

// Extraterrestrial solar spectral irradiance, W/m2/nm, band means.
extern const Spectrum kExtraterrestrial;

// Anderson et al. (1986) standard atmospheres, which set the Rayleigh scattering at sea
// level and its scale height (RADIANCE 6's genssky picks one by latitude and season).
enum class RayleighProfile {
    MidlatitudeSummer,
    MidlatitudeWinter,
    SubarcticSummer,
    SubarcticWinter,
    Tropical
};
// Poleward of 67 degrees subarctic, equatorward of 23 tropical, else midlatitude; summer
// is April to September in the north, October to March in the south.
RayleighProfile rayleighProfileFor(double latitudeRadians, int month);
// Two letters naming the profile in cache files ("ms", "mw", "ss", "sw", "tr").
const char* profileTag(RayleighProfile p);

struct Model {
    double rayleighScaleHeight = 8820;  // m
    Spectrum rayleigh{};                // scattering coefficient at sea level, 1/m
    // Aerosol (Mie) scattering coefficient, 1/m, every kMieStep metres from the ground to
    // the top; aerosols are taken not to absorb.
    static constexpr double kMieStep = 50;
    std::vector<Spectrum> mie;
    double groundAlbedo = 0.2;

    // `mieTable`: a RADIANCE data file over altitude (m) and band index 0..19 (genssky's
    // mie_ca.dat format), times `mieScale`. InputError if it has another shape.
    static Model make(RayleighProfile profile, const calc::DataFile& mieTable, double mieScale,
                      double groundAlbedo);

    double rayleighDensity(double height) const;  // relative to sea level
    static double ozoneDensity(double height);    // relative to its 25 km peak
    Spectrum mieAt(double height) const;
    static const Spectrum& ozoneAbsorption();  // 1/m at the peak
};

// Table sizes and scattering orders. The defaults are RADIANCE 6.1a's.
struct Resolution {
    int transmittanceR = 64, transmittanceMu = 256;
    int scatteringR = 16, scatteringMu = 64, scatteringMuS = 16, scatteringNu = 4;
    int irradianceR = 16, irradianceMuS = 64;
    int orders = 4;  // scattering orders (1: single scattering only)
};

class Atmosphere {
public:
    // Precomputes every table; the result is the same for any number of threads.
    static Atmosphere compute(const Model& model, const Resolution& res, int threads);

    // Reads tables that save() wrote for `model` at `res` under `key` (which names what
    // they were computed from); false, *this untouched, when the file is missing, short
    // or made for something else.
    bool load(const std::string& path, const Model& model, const Resolution& res,
              const std::string& key);
    // Writes the tables atomically, tagged with `key` (what they were computed for).
    void save(const std::string& path, const std::string& key) const;

    // Spectral radiance (W/m2/sr/nm) seen from `height` metres above the ground in
    // direction `dir` (unit, z up) with the sun towards `sun`: the sky, or where the ray
    // meets the ground, the light scattered on the way plus the ground's reflection.
    Spectrum radiance(const Vec3& dir, const Vec3& sun, double height) const;
    // The sun disc's mean spectral radiance seen from `height` (0 below the horizon).
    Spectrum sunRadiance(const Vec3& sun, double height) const;
    // Indirect (sky) irradiance on a horizontal surface at radius r, sun cosine muS.
    Spectrum indirectIrradiance(double r, double muS) const;
    // Transmittance from radius r along cosine mu to the top of the atmosphere.
    Spectrum transmittanceToTop(double r, double mu) const;

    const Model& model() const { return model_; }

private:
    Spectrum scattered(double r, double mu, double muS, double nu, bool ground) const;
    Spectrum transmittance(double r, double mu, double d, bool ground) const;
    Spectrum transmittanceToSun(double r, double muS) const;

    Model model_;
    Resolution res_;
    std::vector<float> transmittance_;  // [r][mu][band]
    std::vector<float> scattering_;     // [r][mu][muS][nu][band]: Rayleigh, all orders
    std::vector<float> singleMie_;      // the same layout: single Mie scattering
    std::vector<float> irradiance_;     // [r][muS][band]: indirect irradiance
};

}  // namespace rp::gen::atmos
