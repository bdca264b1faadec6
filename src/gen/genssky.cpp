// genssky(1): options, the sky picture, the sun and RADIANCE 6.1a's output layout.
#include "gen/genssky.h"

#include <cmath>
#include <cstring>
#include <filesystem>

#include "calc/data_file.h"
#include "calc/search_path.h"
#include "gen/atmosphere.h"
#include "gen/gen_text.h"
#include "gen/gensky.h"
#include "image/spectral_picture.h"
#include "util/error.h"
#include "util/spectrum.h"

namespace rp::gen {

namespace {

using atmos::kBands;
using atmos::Spectrum;

constexpr double kViewHeight = 10;                 // m above the ground, as RADIANCE's genssky
constexpr double kBandsSpan = 400;                 // nm: a band's radiance per nm times this
constexpr double kWhiteEfficacy = 179;             // lm/W, RADIANCE's WHTEFFICACY
constexpr double kOvercastEfficacy = 203;          // lm/W of the CIE overcast sky's luminance (D65)
constexpr double kGroundNormalisation = 0.777778;  // 7/9: overcast horizontal / (pi zenith)

// Relative spectrum of overcast daylight (correlated colour temperature 6415 K), 20 nm
// bands from 390 nm, mean about 1; RADIANCE 6.1a's genssky's values.
constexpr Spectrum kOvercastSpectrum = {
    0.63231, 1.06171, 1.00779, 1.36423, 1.34133, 1.27258, 1.26276, 1.26352, 1.22201, 1.13246,
    1.0434,  1.05547, 0.98212, 0.94445, 0.9722,  0.82387, 0.87853, 0.82559, 0.75111, 0.78925};

// CIE overcast sky luminance over 203 lm/W (gensky's formula): zenith, and by direction
// (blended to the ground's brightness below the horizon as gensky does).
double overcastZenith(const Vec3& sun) {
    return sun.z < 0 ? 0.0 : (8.6 * sun.z + 0.123) * 1000.0 / kOvercastEfficacy;
}
double overcastBrightness(double dz, double zenith) {
    const double ground = zenith * kGroundNormalisation;
    const double a = std::pow(dz + 1.01, 10), b = std::pow(dz + 1.01, -10);
    return (a * zenith * (1 + 2 * dz) / 3 + b * ground) / (a + b);
}

// genssky's 20 bands as RADIANCE 6 samples them (made once: every pixel's luminance needs it).
const spectral::Sampling& sampling20() {
    static const spectral::Sampling s = spectral::makeSampling(kBands, 380, 780)->sampling;
    return s;
}

// Luminance factor of a spectrum given shortest band first (as the atmosphere's).
double photopic(const Spectrum& s) {
    double longestFirst[kBands];
    for (int b = 0; b < kBands; ++b) longestFirst[b] = s[kBands - 1 - b];
    return spectral::photopic(std::span<const double>(longestFirst, kBands), sampling20());
}

// The picture is read as RADIANCE reads data (specpict): pixels are grid points from
// edge to edge, interpolated between. Pixel (i, j) (j from the top) holds the direction
// skyfunc maps to it: azimuth atan2(Dy, Dx) from -pi at the left to pi at the right,
// elevation from the zenith in the top row to the nadir in the bottom one.
Vec3 pixelDirection(int i, int j, int width, int height) {
    const double phi = kPi * (2.0 * i / (width - 1) - 1);
    const double lambda = kPi * (0.5 - double(j) / (height - 1));
    return {std::cos(lambda) * std::cos(phi), std::cos(lambda) * std::sin(phi), std::sin(lambda)};
}

// Illuminance (lux) the picture's sky gives a horizontal surface, integrating its rows'
// luminance as the renderer interpolates them.
double horizontalIlluminance(const std::vector<Spectrum>& pixels, int width, int height) {
    std::vector<double> rowMean(size_t(height), 0.0);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const double w = (i == 0 || i == width - 1) ? 0.5 : 1.0;  // trapezoid in azimuth
            rowMean[size_t(j)] += w * photopic(pixels[size_t(j) * width + i]) / (width - 1);
        }
    constexpr int kSteps = 1024;
    double e = 0;
    for (int k = 0; k < kSteps; ++k) {
        const double lambda = (k + 0.5) / kSteps * 0.5 * kPi;
        const double f = (0.5 - lambda / kPi) * (height - 1);  // fractional row
        const int j0 = std::min(static_cast<int>(f), height - 2);
        const double l =
            rowMean[size_t(j0)] + (f - j0) * (rowMean[size_t(j0) + 1] - rowMean[size_t(j0)]);
        e += l * std::sin(lambda) * std::cos(lambda) * 2 * kPi * (0.5 * kPi / kSteps);
    }
    return kWhiteEfficacy * e;
}

struct Sky {
    SpectralPicture picture;
    Spectrum sun{};  // per nm, the sun disc's radiance
};

Sky makeSky(const atmos::Atmosphere& atm, const GensskyOptions& opt, const Vec3& sun) {
    const int width = opt.resolution, height = std::max(2, opt.resolution / 2);
    Sky sky;
    sky.picture = SpectralPicture(width, height, sampling20());
    // RADIANCE's reader of hyperspectral data (getspec) needs WAVELENGTH_SPLITS=.
    sky.picture.header.lines = {"NCOMP=20", "WAVELENGTH_SPLITS= 780 588 480 380"};
    sky.picture.paddedResolution = true;  // as RADIANCE's fputsresolu
    const double zenith = overcastZenith(sun);
    const double c = opt.cloudCover;
    std::vector<Spectrum> pixels(size_t(width) * height);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const Vec3 d = pixelDirection(i, j, width, height);
            Spectrum l = atm.radiance(d, sun, kViewHeight);
            const double overcast =
                d.z < 0 ? zenith * kGroundNormalisation : overcastBrightness(d.z, zenith);
            for (int b = 0; b < kBands; ++b)
                l[b] = (1 - c) * l[b] * kBandsSpan + c * overcast * kOvercastSpectrum[b];
            pixels[size_t(j) * width + i] = l;
        }
    // -L: the sky scaled to the measured diffuse horizontal illuminance.
    double scale = 1;
    if (opt.diffuseHorizontal > 0) {
        const double e = horizontalIlluminance(pixels, width, height);
        if (e > 0) scale = opt.diffuseHorizontal / e;
    }
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const Spectrum& l = pixels[size_t(j) * width + i];
            auto out = sky.picture.at(i, j);
            for (int b = 0; b < kBands; ++b) out[size_t(b)] = float(scale * l[kBands - 1 - b]);
        }
    sky.sun = atm.sunRadiance(sun, kViewHeight);
    const double sunOvercast = overcastBrightness(sun.z, zenith);
    for (int b = 0; b < kBands; ++b)
        sky.sun[b] = (1 - c) * sky.sun[b] + c * kOvercastSpectrum[b] * sunOvercast / kBandsSpan;
    return sky;
}

// A stable fingerprint of the aerosol table, so that cached tables follow its changes.
uint64_t fingerprint(const atmos::Model& m) {
    uint64_t h = 1469598103934665603ull;
    for (const Spectrum& s : m.mie)
        for (double v : s) {
            uint64_t bits;
            std::memcpy(&bits, &v, sizeof bits);
            h = (h ^ bits) * 1099511628211ull;
        }
    return h;
}

atmos::Atmosphere atmosphereFor(const GensskyOptions& opt, const atmos::Model& model,
                                const std::string& tag, std::string& text) {
    const atmos::Resolution res{.orders = opt.orders};
    const std::string dir = opt.dataDir + "/atmos_data";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (!std::filesystem::is_directory(dir))
        throw InputError("cannot create atmos_data directory '" + dir + "'");
    const std::string key =
        cformat("%s g=%.17g orders=%d mie=%016llx", tag.c_str(), model.groundAlbedo, opt.orders,
                static_cast<unsigned long long>(fingerprint(model)));
    const std::string path =
        dir + "/radphoton_" + tag + cformat("_g%.2f_i%d.atm", model.groundAlbedo, opt.orders);
    atmos::Atmosphere a;
    if (a.load(path, model, res, key)) return a;
    text += "# Pre-computing...\n";
    a = atmos::Atmosphere::compute(model, res, opt.threads);
    a.save(path, key);
    return a;
}

std::string sceneText(const std::vector<std::string>& args, const GensskyOptions& opt,
                      const Sky& sky, const Vec3& sun, const std::string& skyFile) {
    std::string t = "# ";
    for (const std::string& a : args) t += a + " ";
    t += cformat("\n#Cloud cover: %g\n#Ground reflectance: %g\n#Sky map resolution: %d\n\n",
                 opt.cloudCover, opt.groundReflectance, opt.resolution);
    if (sun.z > 0) {
        double mean = 0;
        for (double v : sky.sun) mean += v / kBands;
        Spectrum unit{};
        for (int b = 0; b < kBands; ++b) unit[b] = mean > 0 ? sky.sun[b] / mean : 1.0;
        double intensity = mean * kBandsSpan;
        // -L: the sun's luminance times its solid angle is the direct normal illuminance.
        if (opt.directNormal > 0)
            intensity =
                opt.directNormal / (atmos::kSunSolidAngle * kWhiteEfficacy * photopic(unit));
        t += "void spectrum sunrad\n0\n0\n22 390 770 ";
        for (double v : unit) t += cformat("%.3f ", v);
        t += cformat("\n\nsunrad light solar\n0\n0\n3 %.1f %.1f %.1f\n\n", intensity, intensity,
                     intensity);
        t += cformat("solar source sun\n0\n0\n4 %f %f %f 0.533\n\n", sun.x, sun.y, sun.z);
    }
    t += "void specpict skyfunc\n5 noop " + skyFile +
         " . 'Atan2(Dy,Dx)/PI+1' '1-Acos(Dz)/PI'\n0\n0\n\n";
    return t;
}

}  // namespace

GensskyOptions parseGensskyArgs(const std::vector<std::string>& args) {
    GensskyOptions opt;
    if (args.size() == 2 && args[1] == "-defaults") {
        opt.printDefaults = true;
        return opt;
    }
    if (args.size() < 4)
        throw InputError(
            "usage: genssky month day hour [-y year] [-a lat] [-o lon] [-m meridian] [-d aod] "
            "[-c cloud_cover] [-l mie_file] [-p dir] [-g grefl] [-L dirnorm_illum "
            "difhor_illum] [-n nproc] [-r res] [-f prefix] [-i orders]");
    opt.month = parseInt(args[1], "month");
    opt.day = parseInt(args[2], "day");
    checkDate(opt.month, opt.day);
    const bool zoneMeridian = parseClockTime(args[3], opt.hour, opt.solarTime, opt.site);
    OptionTable table = genOptionTable();
    auto real = [&](const char* name, const char* what, double& v, double lo, double hi) {
        table.add(realOption(name, what, [&v, name, what, lo, hi](double x) {
            if (!(x >= lo && x <= hi))
                throw InputError(cformat("%s %g outside %g..%g", what, x, lo, hi) + " (" + name +
                                 ")");
            v = x;
        }));
    };
    table.add(realOption("-a", "latitude", [&opt](double v) { opt.site.latitude = v * kDegree; }));
    table.add(
        realOption("-o", "longitude", [&opt](double v) { opt.site.longitude = v * kDegree; }));
    table.add(realOption("-m", "meridian", [&opt, zoneMeridian](double v) {
        if (!zoneMeridian) opt.site.meridian = v * kDegree;  // a time zone wins, as gensky
    }));
    table.add(intOption("-y", "year", [&opt](int y) { opt.year = y; }));
    real("-d", "aerosol optical depth", opt.aerosolDepth, 0, 10);
    real("-c", "cloud cover", opt.cloudCover, 0, 1);
    real("-g", "ground reflectance", opt.groundReflectance, 0, 1);
    table.add(customOption("-l", [&opt](OptionReader& r) { opt.mieFile = r.word(); }));
    table.add(customOption("-p", [&opt](OptionReader& r) { opt.dataDir = r.word(); }));
    table.add(customOption("-f", [&opt](OptionReader& r) { opt.prefix = r.word(); }));
    table.add(customOption("-L", [&opt](OptionReader& r) {
        opt.directNormal = r.real();
        opt.diffuseHorizontal = r.real();
        r.require(opt.directNormal >= 0 && opt.diffuseHorizontal >= 0,
                  "illuminances must not be negative");
    }));
    table.add(intOption("-n", "number of threads", [&opt](int n) {
        if (n < 1) throw InputError("number of threads must be at least 1 (-n)");
        opt.threads = n;
    }));
    table.add(intOption("-r", "resolution", [&opt](int n) {
        if (n < 2 || n > 8192) throw InputError("resolution must be 2..8192 (-r)");
        opt.resolution = n;
    }));
    table.add(intOption("-i", "scattering order", [&opt](int n) {
        if (n < 2 || n > 20) throw InputError("scattering order must be 2..20 (-i)");
        opt.orders = n;
    }));
    std::vector<std::string> words = args;
    table.parseAll(words, 4);
    while (opt.dataDir.size() > 1 && opt.dataDir.back() == '/') opt.dataDir.pop_back();
    return opt;
}

std::string gensskyDefaults(const GensskyOptions& opt) {
    return cformat("-i %d\t\t\t\t#scattering order\n", opt.orders) +
           cformat("-g %f\t\t\t#ground reflectance\n", opt.groundReflectance) +
           cformat("-c %f\t\t\t#cloud cover\n", opt.cloudCover) +
           cformat("-r %d\t\t\t\t#image resolution\n", opt.resolution) +
           cformat("-d %f\t\t\t#broadband aerosol optical depth\n", opt.aerosolDepth) +
           cformat("-f %s\t\t\t\t#output name (-f)\n", opt.prefix.c_str()) +
           cformat("-p %s\t\t\t\t#atmos data directory\n", opt.dataDir.c_str());
}

std::string genssky(const std::vector<std::string>& args,
                    const std::vector<std::string>& searchPath,
                    std::vector<std::string>* warnings) {
    const GensskyOptions opt = parseGensskyArgs(args);
    if (opt.printDefaults) return gensskyDefaults(opt);
    auto warn = [&](const std::string& w) {
        if (warnings) warnings->push_back(w);
    };
    if (opt.year && (opt.year < 1950 || opt.year > 2050))
        warn("warning - year should be in range 1950-2050");
    if (!opt.solarTime && std::fabs(opt.site.meridian - opt.site.longitude) > 45 * kDegree)
        warn(cformat("warning - %.1f hours btwn. standard meridian and longitude",
                     (opt.site.longitude - opt.site.meridian) * 12 / kPi));
    const SunPosition p =
        sunPosition(opt.site, opt.year, opt.month, opt.day, opt.hour, opt.solarTime);
    const Vec3 sun = sunDirection(p.altitude, p.azimuth);

    const auto mieFile = calc::findFile(opt.mieFile, searchPath);
    if (!mieFile) throw InputError("cannot find aerosol file '" + opt.mieFile + "'");
    const atmos::RayleighProfile profile = atmos::rayleighProfileFor(opt.site.latitude, opt.month);
    // RADIANCE's default file holds an aerosol optical depth of 0.115; -d scales it.
    const atmos::Model model = atmos::Model::make(profile, calc::DataFile::load(*mieFile),
                                                  opt.aerosolDepth / 0.115, opt.groundReflectance);
    const std::string stem = std::filesystem::path(opt.mieFile).stem().string();
    const std::string tag =
        cformat("%s_%s_%.2f", atmos::profileTag(profile), stem.c_str(), opt.aerosolDepth);
    std::string text;
    const atmos::Atmosphere atm = atmosphereFor(opt, model, tag, text);

    const Sky sky = makeSky(atm, opt, sun);
    const std::string skyFile = opt.dataDir + "/" + opt.prefix + "_sky.hsr";
    writeSpectralPicture(skyFile, sky.picture);
    return text + sceneText(args, opt, sky, sun, skyFile);
}

}  // namespace rp::gen
