// gendaymtx(1): options, the loop over the weather tape (sun position, the step's sky,
// the sun file, the running average) and the matrix output (see gendaymtx.h).
#include "gen/gendaymtx.h"

#include <bit>
#include <cmath>
#include <cstring>

#include "gen/gen_text.h"
#include "gen/sun_position.h"
#include "util/error.h"

namespace rp::gen {

namespace {

constexpr const char* kUsage =
    "usage: gendaymtx [-v][-h][-A][-d|-s|-n][-u][-D file [-M modfile]][-r deg][-m N]"
    "[-g r g b][-c r g b][-o{f|d}][-O{0|1}] [tape.wea]";
constexpr double kSunHalfAngle = 0.533 / 2 * kDegree;

// Reads the values of the option at args[i], advancing i.
class ArgReader {
public:
    ArgReader(const std::vector<std::string>& args, size_t& i) : args_(args), i_(i) {}
    const std::string& word() {
        if (i_ + 1 >= args_.size())
            throw InputError("option " + args_[start_] + " needs a value; " + kUsage);
        return args_[++i_];
    }
    double real(const std::string& what) { return parseReal(word(), what); }
    DaymtxColor color(const std::string& what) {
        DaymtxColor c;
        for (float& v : c) v = static_cast<float>(real(what));
        return c;
    }

private:
    const std::vector<std::string>& args_;
    size_t& i_;
    size_t start_ = i_;
};

void noMatrix(GendaymtxOptions& opt) {
    opt.matrix = DaymtxMatrix::None;
    opt.subdivisions = 1;
    opt.sky.skyColor = opt.sky.groundReflectance = DaymtxColor{0, 0, 0};
}

// The options without values.
bool flagOption(const std::string& a, GendaymtxOptions& opt) {
    if (a == "-v")
        opt.verbose = true;
    else if (a == "-h")
        opt.header = false;
    else if (a == "-oa" || a == "-of" || a == "-od")
        opt.format = a[2];
    else if (a == "-O0" || a == "-O1")
        opt.sky.solarRadiance = a[2] == '1';
    else if (a == "-n")
        noMatrix(opt);
    else if (a == "-d")
        opt.sky.skyColor = opt.sky.groundReflectance = DaymtxColor{0, 0, 0};
    else if (a == "-s")
        opt.sky.sunColor = DaymtxColor{0, 0, 0};
    else if (a == "-u")
        opt.sunHoursOnly = true;
    else if (a == "-A")
        opt.matrix = DaymtxMatrix::Average;
    else
        return false;
    return true;
}

}  // namespace

GendaymtxOptions parseGendaymtxArgs(const std::vector<std::string>& args) {
    GendaymtxOptions opt;
    size_t i = 1;
    for (; i < args.size() && !args[i].empty() && args[i][0] == '-'; ++i) {
        const std::string& a = args[i];
        ArgReader r(args, i);
        if (flagOption(a, opt)) continue;
        if (a == "-g") {
            opt.sky.groundReflectance = r.color("ground reflectance");
        } else if (a == "-c") {
            opt.sky.skyColor = r.color("sky color");
        } else if (a == "-m") {
            opt.subdivisions = parseInt(r.word(), "subdivision count");
            if (opt.subdivisions < 1) throw InputError("-m must be 1 or more");
        } else if (a == "-r" || a == "-rz") {
            opt.rotationDeg = r.real("rotation");
        } else if (a == "-D") {
            opt.sunFile = r.word();
            // RADIANCE compat: suns on the standard output mean no matrix (unless a
            // later -A), and no sky.
            if (opt.sunFile == "-") noMatrix(opt);
        } else if (a == "-M") {
            opt.modifierFile = r.word();
        } else if (a == "-5") {
            double radius = kPi / 360 * r.real("solar disk size");
            if (radius <= 0) throw InputError("missing solar disk size argument for '-5' option");
            opt.sky.sunPatches = 1;
            opt.sky.fixedSunSolidAngle = radius * (radius * kPi);
        } else {
            throw InputError("unknown option '" + a + "'; " + kUsage);
        }
    }
    if (i + 1 < args.size()) throw InputError(std::string("too many arguments; ") + kUsage);
    if (i + 1 == args.size()) opt.input = args[i];
    return opt;
}

namespace {

// The loop state: the matrix columns stored so far (with -A, column 0 accumulates and
// column 1 takes the current step), the time step count and the leap day shift.
class DaymtxRun {
public:
    DaymtxRun(const GendaymtxOptions& opt, const WeaTape& tape, const std::string& tapeName,
              GendaymtxOutputs& out)
        : opt_(opt),
          tape_(tape),
          name_(tapeName),
          out_(out),
          sky_(makeReinhartSky(opt.subdivisions)) {
        site_.latitude = tape.header.latitude * kDegree;
        site_.longitude = tape.header.longitude * kDegree;
        site_.meridian = tape.header.timeZone * kDegree;
    }

    void run() {
        for (const WeaRecord& r : tape_.records) step(r);
        if (steps_ == 0) throw InputError(SourceLoc{name_, 0}, "no valid time steps on input");
        if (opt_.matrix == DaymtxMatrix::Average && steps_ > 1) {
            const double inverse = 1.0 / steps_;
            for (int i = 0; i < 3 * sky_.size(); ++i)
                data_[i] = static_cast<float>(data_[i] * inverse);
        }
    }
    const ReinhartSky& sky() const { return sky_; }
    const std::vector<float>& data() const { return data_; }
    int columns() const { return stored_; }

private:
    void note(const std::string& s) {
        if (out_.note) out_.note(s);
    }
    void step(const WeaRecord& r);
    void sunText(int minute, bool lit, double directIlluminance, const DaymtxStep& s) {
        *out_.suns << daymtxSunText(minute, lit, directIlluminance, s, opt_.sky.sunColor);
        if (out_.modifiers) *out_.modifiers << cformat("solar%d\n", minute);
    }

    const GendaymtxOptions& opt_;
    const WeaTape& tape_;
    const std::string& name_;
    GendaymtxOutputs& out_;
    ReinhartSky sky_;
    Site site_;
    std::vector<float> data_;
    int stored_ = 0, steps_ = 0, lastMonth_ = 0, leapDay_ = 0;
};

void DaymtxRun::step(const WeaRecord& r) {
    const bool photometric = tape_.header.units == WeaUnits::DirectNormalIlluminance;
    DaymtxStep s;
    s.photometric = photometric;
    // RADIANCE compat (gendaymtx.c main): after a February 29 every later date is a day
    // further into the year.
    if (r.month == 2 && r.day == 29) {
        s.julianDate = 60;
        leapDay_ = 1;
    } else {
        s.julianDate = dayOfYear(r.month, r.day) + leapDay_;
    }
    const double declination = solarDeclination(s.julianDate);
    const double solarTime = r.hour + solarTimeAdjustment(s.julianDate, site_);
    s.altitude = solarAltitude(site_, declination, solarTime);
    const bool sunInSky = s.altitude > -kSunHalfAngle;
    if (opt_.sunHoursOnly && !sunInSky) return;
    s.azimuth = solarAzimuth(site_, declination, solarTime) + kPi - opt_.rotationDeg * kDegree;

    const size_t n = 3 * static_cast<size_t>(sky_.size());
    const size_t offset = n * stored_;
    if (opt_.matrix == DaymtxMatrix::PerStep || stored_ == 0) ++stored_;
    if (data_.size() < offset + n) data_.resize(offset + n);
    float* patches = data_.data() + offset;
    ++steps_;
    const int minute = 24 * 60 * (s.julianDate - 1) + static_cast<int>(r.hour * 60 + 0.5);
    if (r.direct + r.diffuse <= 1e-4) {  // night, in effect
        std::memset(patches, 0, n * sizeof(float));
        if (out_.suns && sunInSky) sunText(minute, false, 0, s);
        return;
    }
    if (r.direct < 0 || r.diffuse < 0)
        throw InputError(SourceLoc{name_, r.line}, "negative direct or diffuse value");
    if (!sunInSky && r.direct > (photometric ? 20 * 179.0 : 20.0))
        note(cformat("warning - unusually bright at %.1f on %d-%d", r.hour, r.month, r.day));
    s.direct = r.direct;
    s.diffuse = r.diffuse;
    if (tape_.header.units == WeaUnits::DirectHorizontalIrradiance && s.altitude > 1e-6)
        s.direct /= std::sin(s.altitude);
    const DaymtxPerez perez = daymtxPerez(s, opt_.sky.solarRadiance);
    computeSkyPatches(sky_, opt_.sky, s, perez, patches);
    if (out_.suns && sunInSky) sunText(minute, true, perez.directIlluminance, s);
    if (opt_.matrix == DaymtxMatrix::None) return;
    addDirectSun(sky_, opt_.sky, s, perez.directIlluminance, patches);
    if (opt_.matrix == DaymtxMatrix::Average && steps_ > 1)
        for (size_t i = 0; i < n; ++i) data_[i] += patches[i];
    if (opt_.verbose && r.month != lastMonth_)
        note(cformat("stepping through month %d...", lastMonth_ = r.month));
}

const char* formatName(char format) {
    return format == 'f' ? "float" : format == 'd' ? "double" : "ascii";
}

std::string matrixHeader(const GendaymtxOptions& opt, const WeaTape& tape,
                         const std::vector<std::string>& args, int rows, int columns) {
    std::string h = "#?RADIANCE\n";
    for (size_t i = 0; i < args.size(); ++i) h += (i ? " " : "") + headerWord(args[i]);
    h += "\n";
    // RADIANCE compat: the site goes through radians and back, as gendaymtx keeps it.
    h += cformat("LATLONG= %.8f %.8f\n", tape.header.latitude * kDegree * (180.0 / kPi),
                 -(tape.header.longitude * kDegree * (180.0 / kPi)));
    h += cformat("NROWS=%d\nNCOLS=%d\nNCOMP=3\n", rows, columns);
    if (opt.format != 'a')
        h += std::endian::native == std::endian::big ? "BigEndian=1\n" : "BigEndian=0\n";
    h += cformat("FORMAT=%s\n\n", formatName(opt.format));
    return h;
}

// Patches are rows, time steps columns: row by row, a patch's value at every step.
void writeMatrix(const GendaymtxOptions& opt, const DaymtxRun& run, std::ostream& os) {
    const int rows = run.sky().size(), columns = run.columns();
    const std::vector<float>& data = run.data();
    const size_t stride = 3 * static_cast<size_t>(rows);
    std::string text;
    for (int p = 0; p < rows; ++p) {
        text.clear();
        for (int j = 0; j < columns; ++j) {
            const float* v = data.data() + stride * j + 3 * p;
            if (opt.format == 'a') {
                text += cformat("%.3g %.3g %.3g\n", v[0], v[1], v[2]);
            } else if (opt.format == 'f') {
                text.append(reinterpret_cast<const char*>(v), 3 * sizeof(float));
            } else {
                const double d[3] = {v[0], v[1], v[2]};
                text.append(reinterpret_cast<const char*>(d), sizeof d);
            }
        }
        if (opt.format == 'a' && columns > 1) text += '\n';
        os.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
}

}  // namespace

void runGendaymtx(const GendaymtxOptions& opt, const WeaTape& tape, const std::string& tapeName,
                  const std::vector<std::string>& args, GendaymtxOutputs& out) {
    auto note = [&](const std::string& s) {
        if (out.note) out.note(s);
    };
    if (!opt.modifierFile.empty() && opt.sunFile.empty())
        note("warning -M output will be empty without -D");
    if (opt.verbose) {
        note(opt.input.empty() ? std::string("reading weather tape from <stdin>")
                               : "reading weather tape '" + opt.input + "'");
        note("location '" + tape.header.place + "'");
        note(cformat("(lat,long)=(%.1f,%.1f) degrees north, west", tape.header.latitude,
                     tape.header.longitude));
    }
    DaymtxRun run(opt, tape, tapeName, out);
    if (opt.verbose) {
        if (opt.matrix != DaymtxMatrix::None) note(cformat("%d sky patches", run.sky().size()));
        if (!opt.sunFile.empty()) note("outputting suns to file");
        if (opt.rotationDeg != 0) note(cformat("rotating output %.0f degrees", opt.rotationDeg));
    }
    run.run();
    if (opt.matrix != DaymtxMatrix::None && out.matrix) {
        if (opt.verbose)
            note(cformat("writing %smatrix with %d time steps...",
                         opt.format == 'a' ? "" : "binary ", run.columns()));
        if (opt.header)
            *out.matrix << matrixHeader(opt, tape, args, run.sky().size(), run.columns());
        writeMatrix(opt, run, *out.matrix);
    }
    if (opt.verbose) note("done.");
}

}  // namespace rp::gen
