// gendaylit(1): option parsing, the Perez sky computation in gendaylit's order (sun
// position, clearness/brightness, efficacies, coefficients, normalisation over the 145
// Tregenza patches, ground brightness) and its output layout, including the "error sky"
// it prints (exit status 0) when the sun is down or the measurements are impossible.
#include "gen/gendaylit.h"

#include <cmath>

#include "gen/cie_sky.h"
#include "gen/gen_text.h"
#include "gen/perez.h"
#include "util/error.h"

namespace rp::gen {

namespace {

constexpr double kWhiteEfficacy = 179.0;  // lm/W, RADIANCE WHTEFFICACY
constexpr double kHalfSunAngle = 0.2665;  // degrees
// Limits gendaylit clamps epsilon and Delta to.
constexpr double kClearMin = 1.0, kClearMax = 12.01, kBrightMin = 0.01, kBrightMax = 0.6;

// Thrown inside the computation where gendaylit prints its error sky and stops.
struct ErrorSky {};

struct Computation {
    const GendaylitOptions& opt;
    GendaylitSky& sky;
    double zenithDeg = 0;
    double dayNumber = 0;

    void warn(const std::string& w) {
        if (!opt.quiet) sky.warnings.push_back(w);
    }
    void errorSky(const std::string& w) {
        warn(w);
        throw ErrorSky{};
    }
    void clampParameters() {
        if (sky.epsilon < kClearMin) sky.epsilon = kClearMin;
        if (sky.epsilon > kClearMax) sky.epsilon = kClearMax - 0.001;
        if (sky.delta < kBrightMin) sky.delta = kBrightMin;
        if (sky.delta > kBrightMax) sky.delta = kBrightMax;
    }
    // gendaylit's air_mass() limits the zenith angle to 90 for everything after it.
    void limitZenith() {
        if (zenithDeg > 90) {
            warn("Warning: air mass has reached the maximal value");
            zenithDeg = 90;
        }
    }
    void checkIrradiances() {
        if (sky.directIrradiance < 0) {
            warn("Warning: direct irradiance < 0. Using 0.0");
            sky.directIrradiance = 0;
        }
        if (sky.diffuseIrradiance < 0) {
            warn("Warning: diffuse irradiance < 0. Using 0.0");
            sky.diffuseIrradiance = 0;
        }
        if (sky.directIrradiance + sky.diffuseIrradiance == 0 && sky.altitude > 0)
            errorSky("Warning: zero irradiance at sun altitude > 0, printing error sky");
        if (sky.directIrradiance > kSolarConstantW)
            errorSky("Warning: direct irradiance exceeds solar constant");
    }
    void checkIlluminances() {
        if (sky.directIlluminance < 0) {
            warn("Warning: direct illuminance < 0. Using 0.0");
            sky.directIlluminance = 0;
        }
        if (sky.diffuseIlluminance < 0) {
            warn("Warning: diffuse illuminance < 0. Using 0.0");
            sky.diffuseIlluminance = 0;
        }
        if (sky.directIlluminance + sky.diffuseIlluminance == 0 && sky.altitude > 0)
            errorSky("Warning: zero illuminance at sun altitude > 0, printing error sky");
        if (sky.directIlluminance > kSolarConstantLux)
            errorSky("Warning: direct illuminance exceeds solar constant");
    }
    double diffuseEff() {
        double e = diffuseEfficacy(sky.epsilon, sky.delta, zenithDeg, sky.water);
        if (e < 0)
            errorSky(cformat("Warning: sky clearness (= %.3f) too high, printing error sky",
                             sky.epsilon));
        return e;
    }
    double directEff() { return directEfficacy(sky.epsilon, sky.delta, zenithDeg, sky.water); }
    // Clearness and brightness from the irradiances (paths -W, -G, -E).
    void fromIrradiances() {
        checkIrradiances();
        limitZenith();
        sky.delta = perezBrightness(sky.diffuseIrradiance, zenithDeg, dayNumber);
        sky.epsilon = perezClearness(sky.diffuseIrradiance, sky.directIrradiance, zenithDeg);
        clampParameters();
        illuminancesFromIrradiances();
    }
    void illuminancesFromIrradiances() {
        if (opt.output == 1) return;
        sky.diffuseIlluminance = sky.diffuseIrradiance * diffuseEff();
        sky.directIlluminance = sky.directIrradiance * directEff();
        checkIlluminances();
    }
    // gendaylit's illu_to_irra_index(): iterate irradiance <- illuminance / efficacy.
    void irradiancesFromIlluminances() {
        double test1 = 0.1, test2 = 0.1;
        int counter = 0;
        sky.diffuseIrradiance = sky.diffuseIlluminance * kSolarConstantW / kSolarConstantLux;
        sky.directIrradiance = sky.directIlluminance * kSolarConstantW / kSolarConstantLux;
        limitZenith();
        sky.epsilon = perezClearness(sky.diffuseIrradiance, sky.directIrradiance, zenithDeg);
        sky.delta = perezBrightness(sky.diffuseIrradiance, zenithDeg, dayNumber);
        clampParameters();
        // RADIANCE compat: the loop condition holds whenever the parameters are in range,
        // so in practice it runs its 9 iterations.
        auto outside = [&] {
            return (sky.epsilon < kClearMin || sky.epsilon > kClearMax) ||
                   (sky.delta < kBrightMin || sky.delta > kBrightMax);
        };
        while ((std::fabs(sky.diffuseIrradiance - test1) > 10 ||
                std::fabs(sky.directIrradiance - test2) > 10 || !outside()) &&
               counter != 9) {
            test1 = sky.diffuseIrradiance;
            test2 = sky.directIrradiance;
            ++counter;
            sky.diffuseIrradiance = sky.diffuseIlluminance / diffuseEff();
            double dEff = directEff();
            sky.directIrradiance = dEff < 0.1 ? 0 : sky.directIlluminance / dEff;
            sky.delta = perezBrightness(sky.diffuseIrradiance, zenithDeg, dayNumber);
            sky.epsilon = perezClearness(sky.diffuseIrradiance, sky.directIrradiance, zenithDeg);
            clampParameters();
        }
    }

    void run() {
        double alt = sky.altitude;
        zenithDeg = 90 - alt / kDegree;
        switch (opt.input) {
            case DaylitInput::Perez:
                sky.epsilon = opt.value1;
                sky.delta = opt.value2;
                clampParameters();
                limitZenith();
                sky.diffuseIrradiance = diffuseFromBrightness(sky.delta, zenithDeg, dayNumber);
                sky.directIrradiance =
                    directFromClearness(sky.epsilon, sky.delta, zenithDeg, dayNumber);
                checkIrradiances();
                illuminancesFromIrradiances();
                break;
            case DaylitInput::DirectNormal:
                sky.directIrradiance = opt.value1;
                sky.diffuseIrradiance = opt.value2;
                fromIrradiances();
                break;
            case DaylitInput::Illuminance:
                sky.directIlluminance = opt.value1;
                sky.diffuseIlluminance = opt.value2;
                checkIlluminances();
                irradiancesFromIlluminances();
                break;
            case DaylitInput::DirectHorizontal:
                sky.directIrradiance = opt.value1;
                sky.diffuseIrradiance = opt.value2;
                if (alt <= 0) {
                    warn("Warning: sun altitude < 0, proceed with irradiance values of zero");
                    sky.directIrradiance = sky.diffuseIrradiance = 0;
                } else {
                    sky.directIrradiance /= std::sin(alt);
                }
                fromIrradiances();
                break;
            case DaylitInput::Global: {
                double global = opt.value1;
                if (alt <= 0) {
                    if (global > 50)
                        warn(
                            "Warning: global irradiance higher than 50 W/m^2 while the sun "
                            "altitude is lower than zero");
                    sky.directIrradiance = sky.diffuseIrradiance = 0;
                } else {
                    double s0 = kSolarConstantW * eccentricity(dayNumber) * std::sin(alt);
                    if (global > s0) {
                        warn(
                            "Warning: global irradiance is higher than the time-dependent "
                            "solar constant s0");
                        global = s0 * 0.999;
                    }
                    double kt = global / s0;  // Erbs, Klein & Duffie 1982 diffuse fraction
                    double fraction = kt <= 0.22 ? 1 - 0.09 * kt
                                      : kt <= 0.8
                                          ? 0.9511 - 0.1604 * kt + 4.388 * kt * kt -
                                                16.638 * kt * kt * kt + 12.336 * kt * kt * kt * kt
                                          : 0.165;
                    sky.diffuseIrradiance = global * fraction;
                    sky.directIrradiance = global - sky.diffuseIrradiance;
                    sky.comments.push_back(
                        cformat("# erbs_s0, erbs_kt, irr_dir_h, irr_diff: "
                                "%.3f %.3f %.3f %.3f",
                                s0, kt, sky.directIrradiance, sky.diffuseIrradiance));
                    sky.comments.push_back(
                        "# WARNING: the -E option is only recommended for a rough estimation!");
                    sky.directIrradiance /= std::sin(alt);
                }
                fromIrradiances();
                break;
            }
        }

        double Z = zenithDeg * kDegree;
        sky.coeffs = perezCoefficients(Z, sky.epsilon, sky.delta);
        double integral = perezHorizontalIntegral(sky.coeffs, Z);
        double sunSolidAngle = 2 * kPi * (1 - std::cos(kHalfSunAngle * kDegree));
        switch (opt.output) {
            case 0:
                sky.diffuseNormalisation = sky.diffuseIlluminance / integral / kWhiteEfficacy;
                sky.solarRadiance = sky.directIlluminance / sunSolidAngle / kWhiteEfficacy;
                break;
            case 1:
                sky.diffuseNormalisation = sky.diffuseIrradiance / integral;
                sky.solarRadiance = sky.directIrradiance / sunSolidAngle;
                break;
            default:
                sky.diffuseNormalisation = sky.diffuseIlluminance / integral;
                sky.solarRadiance = sky.directIlluminance / sunSolidAngle;
                break;
        }
        // Ground: the zenith value times gensky's normalisation for the CIE sky type
        // nearest the Perez clearness, plus the sun, times the reflectance.
        sky.zenithBrightness =
            perezRelativeLuminance(sky.coeffs, 0.0, Z) * sky.diffuseNormalisation;
        double norm = 0.777778;
        if (sky.epsilon >= 6)
            norm = skyNormalisationFit(alt, false) / clearSkyF2(alt) / kPi;
        else if (sky.epsilon > 1)
            norm = skyNormalisationFit(alt, true) / intermediateSkyF2(alt) / kPi;
        double ground = sky.zenithBrightness * norm;
        if (opt.sun && sky.epsilon > 1) ground += 6.8e-5 / kPi * sky.solarRadiance * sky.sunDir.z;
        sky.groundBrightness = ground * opt.groundReflectance;
        if (sky.coeffs[1] > 0)
            errorSky(cformat("Warning: positive Perez parameter B (= %lf), printing error sky",
                             sky.coeffs[1]));
        sky.sun = opt.sun;
    }
};

// gendaylit's sunrise/sunset hours (solar time) from the day-of-year declination.
double sunsetHour(const Site& site, int month, int day, bool rise) {
    float w = static_cast<float>(-std::tan(site.latitude) *
                                 std::tan(solarDeclination(dayOfYear(month, day))));
    double half = (kPi / 2 - std::atan2(w, std::sqrt(1 - double(w) * w))) * 180 / (kPi * 15);
    return rise ? 12 - half : 12 + half;
}

}  // namespace

GendaylitOptions parseGendaylitArgs(const std::vector<std::string>& args) {
    if (args.size() < 4)
        throw InputError(
            "usage: gendaylit month day hour [-y year] [options] "
            "{-W dirnorm diffhor | -G dirhor diffhor | -L dirillum diffillum | "
            "-P epsilon delta | -E global} | gendaylit -ang altitude azimuth ...");
    GendaylitOptions opt;
    if (args[1] == "-ang") {
        opt.fromAngles = true;
        opt.altitude = parseReal(args[2], "altitude") * kDegree;
        opt.azimuth = parseReal(args[3], "azimuth") * kDegree;
    } else {
        opt.month = parseInt(args[1], "month");
        opt.day = parseInt(args[2], "day");
        checkDate(opt.month, opt.day);
        opt.solarTime = args[3][0] == '+';
        opt.hour = parseReal(args[3].substr(opt.solarTime ? 1 : 0), "hour");
        if (opt.hour < 0 || opt.hour >= 24)
            throw InputError("bad hour '" + args[3] + "': expected 0 <= hour < 24");
    }
    OptionTable table = genOptionTable();
    table.plusWords = true;
    table.add(wordOption("-s", [&opt] { opt.sun = false; }));
    table.add(wordOption("+s", [&opt] { opt.sun = true; }));
    for (const char* cloudy : {"-c", "+c"})
        table.add(wordOption(cloudy, [&opt] {
            opt.sun = false;
            opt.cloudy = true;
        }));
    table.add(wordOption("-w", [&opt] { opt.quiet = true; }));
    table.add(intOption("-y", "year", [&opt](int year) {
        if (year < 1950 || year > 2050)
            throw InputError("year " + std::to_string(year) +
                             " outside 1950..2050 (Michalsky's almanac algorithm)");
        opt.year = year;
    }));
    table.add(realOption("-a", "latitude", [&opt](double v) { opt.site.latitude = v * kDegree; }));
    table.add(
        realOption("-o", "longitude", [&opt](double v) { opt.site.longitude = v * kDegree; }));
    table.add(realOption("-m", "meridian", [&opt](double v) { opt.site.meridian = v * kDegree; }));
    table.add(
        realOption("-g", "ground reflectance", [&opt](double v) { opt.groundReflectance = v; }));
    table.add(realOption("-d", "dew point", [&opt](double td) {
        opt.dewPoint = (td < -40 || td > 40) ? 10.97353115 : td;  // RADIANCE compat
    }));
    table.add(intOption("-O", "output unit", [&opt](int unit) {
        if (unit < 0 || unit > 2)
            throw InputError("-O must be 0 (visible W), 1 (solar W) or 2 (lumen)");
        opt.output = unit;
    }));
    // The sky measurements: two values, or -E's one.
    auto two = [&](const char* name, DaylitInput in, const char* what) {
        table.add(customOption(name, [&opt, in, what](OptionReader& r) {
            if (r.next() + 1 >= r.args().size())
                throw InputError("option " + r.option() + " needs two values");
            opt.haveInput = true;
            opt.input = in;
            opt.value1 = parseReal(r.word(), what);
            opt.value2 = parseReal(r.word(), what);
        }));
    };
    two("-W", DaylitInput::DirectNormal, "irradiance");
    two("-G", DaylitInput::DirectHorizontal, "irradiance");
    two("-L", DaylitInput::Illuminance, "illuminance");
    two("-P", DaylitInput::Perez, "Perez parameter");
    table.add(realOption("-E", "irradiance", [&opt](double v) {
        opt.haveInput = true;
        opt.input = DaylitInput::Global;
        opt.value1 = v;
    }));
    std::vector<std::string> words = args;
    table.parseAll(words, 4);
    if (!opt.haveInput) throw InputError("no sky measurements: give -W, -G, -L, -P or -E");
    return opt;
}

GendaylitSky computeGendaylit(const GendaylitOptions& opt) {
    GendaylitSky sky;
    sky.water = std::exp(0.07 * opt.dewPoint - 0.075);
    sky.altitude = opt.altitude;
    sky.azimuth = opt.azimuth;
    Computation c{opt, sky};
    try {
        if (!opt.fromAngles) {
            if (!opt.solarTime && std::fabs(opt.site.meridian - opt.site.longitude) > 45 * kDegree)
                c.warn(cformat("warning: %.1f hours btwn. standard meridian and longitude",
                               (opt.site.longitude - opt.site.meridian) * 12 / kPi));
            SunPosition p =
                sunPosition(opt.site, opt.year, opt.month, opt.day, opt.hour, opt.solarTime);
            sky.solarTime = p.solarTime;
            sky.altitude = p.altitude;
            sky.azimuth = p.azimuth;
            c.dayNumber = dayOfYear(opt.month, opt.day);
            if (p.solarTime < sunsetHour(opt.site, opt.month, opt.day, true) ||
                p.solarTime > sunsetHour(opt.site, opt.month, opt.day, false)) {
                sky.sunDir = sunDirection(sky.altitude, sky.azimuth);
                c.errorSky(
                    cformat("Warning: sun altitude below zero at time step %i %i %.2f, "
                            "printing error sky",
                            opt.month, opt.day, opt.hour));
            }
        }
        if (!opt.cloudy && sky.altitude > 87 * kDegree) {
            c.warn("warning - sun too close to zenith, reducing altitude to 87 degrees");
            sky.altitude = 87 * kDegree;
        }
        sky.sunDir = sunDirection(sky.altitude, sky.azimuth);
        c.run();
    } catch (const ErrorSky&) {
        sky.errorSky = true;
        sky.sunDir = sunDirection(sky.altitude, sky.azimuth);
    }
    return sky;
}

std::string formatGendaylit(const GendaylitSky& sky, const std::vector<std::string>& args) {
    std::string out = commandHeader(args, false);
    for (const std::string& line : sky.comments) out += line + "\n";
    out += cformat("# Local solar time: %.2f\n", sky.solarTime);
    out += cformat("# Solar altitude and azimuth: %.1f %.1f\n", sky.altitude / kDegree,
                   sky.azimuth / kDegree);
    const Vec3& d = sky.sunDir;
    if (sky.errorSky) {
        out += "\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n";
        out += cformat("10 0.00 0.00  0.000 0.000 0.000 0.000 0.000  %f %f %f \n", d.x, d.y, d.z);
        return out;
    }
    out += cformat("# epsilon, delta, atmospheric precipitable water content : %.4f %.4f %.4f \n",
                   sky.epsilon, sky.delta, sky.water);
    if (sky.sun) {
        double s = sky.epsilon > 1 ? sky.solarRadiance : 0.0;
        if (sky.epsilon > 1)
            out += cformat("\nvoid light solar\n0\n0\n3 %.3e %.3e %.3e\n", s, s, s);
        else
            out += "\nvoid light solar\n0\n0\n3 0.0 0.0 0.0\n";
        out +=
            cformat("\nsolar source sun\n0\n0\n4 %f %f %f %f\n", d.x, d.y, d.z, 2 * kHalfSunAngle);
    }
    const auto& c = sky.coeffs;
    out += "\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n";
    out += cformat("10 %.3e %.3e %lf %lf %lf %lf %lf %f %f %f \n", sky.diffuseNormalisation,
                   sky.groundBrightness, c[0], c[1], c[2], c[3], c[4], d.x, d.y, d.z);
    return out;
}

std::string gendaylit(const std::vector<std::string>& args, std::vector<std::string>* warnings) {
    GendaylitOptions opt = parseGendaylitArgs(args);
    GendaylitSky sky = computeGendaylit(opt);
    if (warnings) warnings->insert(warnings->end(), sky.warnings.begin(), sky.warnings.end());
    return formatGendaylit(sky, args);
}

}  // namespace rp::gen
