// gensky(1): option parsing (RADIANCE's time syntax with time zones), the sky
// computation (zenith brightness, normalisation, ground brightness, sun radiance) and
// RADIANCE's output layout. Constants: SKYEFFICACY = 203 lm/W (D65) and SUNEFFICACY =
// 208 lm/W, RADIANCE's color.h values since 5.x; they reproduce the daylight validation
// scene's "8.79e+00" zenith and "6.69e+06" sun.
#include "gen/gensky.h"

#include <cctype>
#include <cmath>

#include "gen/cie_sky.h"
#include "gen/gen_text.h"
#include "util/error.h"

namespace rp::gen {

namespace {

constexpr double kSkyEfficacy = 203.0;   // lm/W, RADIANCE D65EFFICACY
constexpr double kSunEfficacy = 208.0;   // lm/W, RADIANCE SUNEFFICACY
constexpr double kSunSolidAngle = 6e-5;  // sr, gensky's 0.5 degree disc

struct TimeZone {
    const char* name;
    double meridianDeg;  // west positive
};
// gensky.1's zones (hours from GMT times 15 degrees). RADIANCE compat: the table holds
// "AST"/"ADT" twice (Atlantic first, Arabia second) and gensky matches the first.
constexpr TimeZone kZones[] = {
    {"YST", 135},  {"YDT", 120},   {"PST", 120},   {"PDT", 105}, {"MST", 105},   {"MDT", 90},
    {"CST", 90},   {"CDT", 75},    {"EST", 75},    {"EDT", 60},  {"AST", 60},    {"ADT", 45},
    {"NST", 52.5}, {"NDT", 37.5},  {"GMT", 0},     {"BST", -15}, {"CET", -15},   {"CEST", -30},
    {"EET", -30},  {"EEST", -45},  {"GST", -60},   {"GDT", -75}, {"IST", -82.5}, {"IDT", -97.5},
    {"JST", -135}, {"NZST", -180}, {"NZDT", -195},
};

}  // namespace

bool parseClockTime(const std::string& word, double& hourOut, bool& solarTime, Site& site) {
    size_t p = 0;
    solarTime = !word.empty() && word[0] == '+';
    if (solarTime) ++p;
    size_t digitsStart = p;
    while (p < word.size() && std::isdigit(static_cast<unsigned char>(word[p]))) ++p;
    bool any = p > digitsStart;
    double hour = any ? std::stod(word.substr(digitsStart, p - digitsStart)) : 0.0;
    if (p < word.size() && word[p] == ':') {
        size_t m0 = ++p;
        while (p < word.size() && std::isdigit(static_cast<unsigned char>(word[p]))) ++p;
        if (p == m0) throw InputError("bad time format '" + word + "'");
        int minutes = std::stoi(word.substr(m0, p - m0));
        if (minutes >= 60) throw InputError("bad minutes in time '" + word + "'");
        hour += minutes / 60.0;
    } else if (p < word.size() && word[p] == '.') {
        size_t f0 = p++;
        while (p < word.size() && std::isdigit(static_cast<unsigned char>(word[p]))) ++p;
        if (p > f0 + 1) hour += std::stod("0" + word.substr(f0, p - f0));
        any = any || p > f0 + 1;
    }
    if (!any) throw InputError("bad time format '" + word + "'");
    if (hour > 24) throw InputError("bad hour '" + word + "': expected 0..24");
    hourOut = hour;
    if (p == word.size()) return false;
    std::string zone = word.substr(p);
    if (solarTime || !std::isalpha(static_cast<unsigned char>(zone[0])))
        throw InputError("bad time format '" + word + "'");
    for (char& c : zone) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const TimeZone& z : kZones)
        if (zone == z.name) {
            site.meridian = z.meridianDeg * kDegree;
            return true;
        }
    std::string known;
    for (const TimeZone& z : kZones) known += std::string(known.empty() ? "" : " ") + z.name;
    throw InputError("unknown time zone '" + word.substr(p) + "' (known: " + known + ")");
}

GenskyOptions parseGenskyArgs(const std::vector<std::string>& args) {
    GenskyOptions opt;
    if (args.size() == 2 && args[1] == "-defaults") {
        opt.printDefaults = true;
        return opt;
    }
    if (args.size() < 4)
        throw InputError(
            "usage: gensky month day hour [options] | -ang altitude azimuth "
            "[options] | -defaults");
    bool zoneMeridian = false;
    if (args[1] == "-ang") {
        opt.fromAngles = true;
        opt.altitude = parseReal(args[2], "altitude") * kDegree;
        opt.azimuth = parseReal(args[3], "azimuth") * kDegree;
    } else {
        opt.month = parseInt(args[1], "month");
        opt.day = parseInt(args[2], "day");
        checkDate(opt.month, opt.day);
        zoneMeridian = parseClockTime(args[3], opt.hour, opt.solarTime, opt.site);
    }
    OptionTable table = genOptionTable();
    table.plusWords = true;
    table.messages.unknown = [](const std::string& w) {
        // RADIANCE compat (gensky.c): a word that cannot be an option is a "bad option".
        const bool optionLike = w.size() == 2 && (w[0] == '-' || w[0] == '+');
        return (optionLike ? "unknown option '" : "bad option '") + w + "'";
    };
    // The sky type: "+s" and "+i" with a sun, "-s" and "-i" without.
    auto sky = [&](const std::string& name, SkyType type) {
        table.add(wordOption(name, [&opt, type, sun = name[0] == '+'] {
            opt.type = type;
            if (type == SkyType::Clear || type == SkyType::Intermediate) opt.sun = sun;
        }));
    };
    sky("-s", SkyType::Clear);
    sky("+s", SkyType::Clear);
    sky("-i", SkyType::Intermediate);
    sky("+i", SkyType::Intermediate);
    sky("-c", SkyType::Overcast);
    sky("+c", SkyType::Overcast);
    sky("-u", SkyType::Uniform);
    sky("+u", SkyType::Uniform);
    // -r/-R solar and -b/-B zenith brightness, as radiance or as irradiance.
    auto given = [&](const std::string& name, const char* what, double& value, GivenAs& as,
                     GivenAs kind) {
        table.add(realOption(name, what, [name, &value, &as, kind](double v) {
            as = kind;
            if (v < 0) throw InputError(name + " value must not be negative");
            value = v;
        }));
    };
    given("-r", "solar value", opt.solar, opt.solarGiven, GivenAs::Radiance);
    given("-R", "solar value", opt.solar, opt.solarGiven, GivenAs::Irradiance);
    given("-b", "zenith value", opt.zenith, opt.zenithGiven, GivenAs::Radiance);
    given("-B", "zenith value", opt.zenith, opt.zenithGiven, GivenAs::Irradiance);
    table.add(realOption("-t", "turbidity", [&opt](double v) { opt.turbidity = v; }));
    table.add(
        realOption("-g", "ground reflectance", [&opt](double v) { opt.groundReflectance = v; }));
    table.add(realOption("-a", "latitude", [&opt](double v) { opt.site.latitude = v * kDegree; }));
    table.add(
        realOption("-o", "longitude", [&opt](double v) { opt.site.longitude = v * kDegree; }));
    table.add(realOption("-m", "meridian", [&opt, zoneMeridian](double v) {
        // RADIANCE compat: a time zone on the hour overrides -m.
        if (!zoneMeridian) opt.site.meridian = v * kDegree;
    }));
    table.add(intOption("-y", "year", [&opt](int year) {
        if (year < 1950 || year > 2050)
            throw InputError("year " + std::to_string(year) +
                             " outside 1950..2050 (Michalsky's almanac algorithm)");
        opt.year = year;
    }));
    std::vector<std::string> words = args;
    table.parseAll(words, 4);
    return opt;
}

GenskySky computeGensky(const GenskyOptions& opt) {
    GenskySky sky;
    sky.type = opt.type;
    bool overcast = opt.type == SkyType::Overcast || opt.type == SkyType::Uniform;
    sky.altitude = opt.altitude;
    sky.azimuth = opt.azimuth;
    if (!opt.fromAngles) {
        if (!opt.solarTime && std::fabs(opt.site.meridian - opt.site.longitude) > 45 * kDegree)
            sky.warnings.push_back(
                cformat("warning - %.1f hours btwn. standard meridian and longitude",
                        (opt.site.longitude - opt.site.meridian) * 12 / kPi));
        SunPosition p =
            sunPosition(opt.site, opt.year, opt.month, opt.day, opt.hour, opt.solarTime);
        sky.fromDate = true;
        sky.solarTime = p.solarTime;
        sky.altitude = p.altitude;
        sky.dateAltitude = p.altitude;
        sky.azimuth = p.azimuth;
    }
    // The CIE clear and intermediate formulas misbehave with the sun at the zenith.
    if (!overcast && sky.altitude > 87 * kDegree) {
        sky.warnings.push_back(
            "warning - sun too close to zenith, reducing altitude to 87 degrees");
        sky.altitudeLimited = true;
        sky.altitude = 87 * kDegree;
    }
    sky.sunDir = sunDirection(sky.altitude, sky.azimuth);
    double sz = sky.sunDir.z;

    double norm = 1.0;  // horizontal diffuse irradiance / (pi * zenith radiance)
    switch (opt.type) {
        case SkyType::Uniform:
            norm = 1.0;
            break;
        case SkyType::Overcast:
            norm = 0.777778;
            break;  // 7/9 for (1 + 2 cos)/3
        case SkyType::Clear:
            sky.f2 = clearSkyF2(sky.altitude);
            norm = skyNormalisationFit(sky.altitude, false) / sky.f2 / kPi;
            break;
        case SkyType::Intermediate:
            sky.f2 = intermediateSkyF2(sky.altitude);
            norm = skyNormalisationFit(sky.altitude, true) / sky.f2 / kPi;
            break;
    }
    // Zenith luminance in kcd/m2: Krochmann (clear, from turbidity), Krochmann/Moon &
    // Spencer overcast 8.6 sin(alt) + .123; intermediate takes the mean of the two.
    double zenith = opt.zenith;
    if (opt.zenithGiven == GivenAs::Irradiance) {
        zenith /= norm * kPi;
    } else if (opt.zenithGiven == GivenAs::Computed) {
        if (overcast)
            zenith = 8.6 * sz + .123;
        else
            zenith = (1.376 * opt.turbidity - 1.81) * std::tan(sky.altitude) + 0.38;
        if (opt.type == SkyType::Intermediate) zenith = (zenith + 8.6 * sz + .123) / 2.0;
        zenith = zenith < 0 ? 0.0 : zenith * 1000.0 / kSkyEfficacy;
    }
    sky.zenithBrightness = zenith;
    sky.groundAmbient = zenith * norm;
    double ground = sky.groundAmbient;
    sky.sun = opt.sun;
    double solar = opt.solar;
    if (!overcast && sz > 0 && (opt.solarGiven == GivenAs::Computed || solar > 0)) {
        if (opt.solarGiven == GivenAs::Irradiance) {
            solar /= kSunSolidAngle * sz;
        } else if (opt.solarGiven == GivenAs::Computed) {
            solar = 1.5e9 / kSunEfficacy * (1.147 - .147 / (sz > .16 ? sz : .16));
            if (opt.type == SkyType::Intermediate) solar *= 0.15;  // RADIANCE's fudge factor
        }
        ground += kSunSolidAngle / kPi * solar * sz;
    } else {
        sky.sun = false;
    }
    sky.solarRadiance = solar;
    sky.groundBrightness = ground * opt.groundReflectance;
    return sky;
}

std::string formatGensky(const GenskySky& sky, const std::vector<std::string>& args) {
    std::string out = commandHeader(args);
    if (sky.fromDate) {
        out += cformat("# Local solar time: %.2f\n", sky.solarTime);
        // RADIANCE compat: the angles are printed before the 87 degree limit.
        out += cformat("# Solar altitude and azimuth: %.1f %.1f\n", sky.dateAltitude / kDegree,
                       sky.azimuth / kDegree);
    }
    if (sky.altitudeLimited)
        out += "# warning - sun too close to zenith, reducing altitude to 87 degrees\n";
    out += cformat("# Ground ambient level: %.1f\n", sky.groundAmbient);
    if (sky.sun) {
        double s = sky.solarRadiance;
        out += cformat("\nvoid light solar\n0\n0\n3 %.2e %.2e %.2e\n", s, s, s);
        out += cformat("\nsolar source sun\n0\n0\n4 %f %f %f 0.5\n", sky.sunDir.x, sky.sunDir.y,
                       sky.sunDir.z);
    }
    out += "\nvoid brightfunc skyfunc\n2 skybr skybright.cal\n0\n";
    if (sky.type == SkyType::Overcast || sky.type == SkyType::Uniform)
        out +=
            cformat("3 %d %.2e %.2e\n", int(sky.type), sky.zenithBrightness, sky.groundBrightness);
    else
        out += cformat("7 %d %.2e %.2e %.2e %f %f %f\n", int(sky.type), sky.zenithBrightness,
                       sky.groundBrightness, sky.f2, sky.sunDir.x, sky.sunDir.y, sky.sunDir.z);
    return out;
}

std::string genskyDefaults(const GenskyOptions& opt) {
    std::string out;
    switch (opt.type) {
        case SkyType::Overcast:
            out += "-c\t\t\t\t# Cloudy sky\n";
            break;
        case SkyType::Uniform:
            out += "-u\t\t\t\t# Uniform cloudy sky\n";
            break;
        case SkyType::Intermediate:
            out += opt.sun ? "+i\t\t\t\t# Intermediate sky with sun\n"
                           : "-i\t\t\t\t# Intermediate sky without sun\n";
            break;
        case SkyType::Clear:
            out += opt.sun ? "+s\t\t\t\t# Sunny sky with sun\n"
                           : "-s\t\t\t\t# Sunny sky without sun\n";
            break;
    }
    out += cformat("-g %f\t\t\t# Ground plane reflectance\n", opt.groundReflectance);
    if (opt.zenith > 0)
        out += cformat("-b %f\t\t\t# Zenith radiance (watts/ster/m2\n", opt.zenith);
    else
        out += cformat("-t %f\t\t\t# Atmospheric turbidity\n", opt.turbidity);
    out += cformat("-a %f\t\t\t# Site latitude (degrees)\n", opt.site.latitude / kDegree);
    out += cformat("-o %f\t\t\t# Site longitude (degrees)\n", opt.site.longitude / kDegree);
    out += cformat("-m %f\t\t\t# Standard meridian (degrees)\n", opt.site.meridian / kDegree);
    return out;
}

std::string gensky(const std::vector<std::string>& args, std::vector<std::string>* warnings) {
    GenskyOptions opt = parseGenskyArgs(args);
    if (opt.printDefaults) return genskyDefaults(opt);
    GenskySky sky = computeGensky(opt);
    if (warnings) warnings->insert(warnings->end(), sky.warnings.begin(), sky.warnings.end());
    return formatGensky(sky, args);
}

}  // namespace rp::gen
