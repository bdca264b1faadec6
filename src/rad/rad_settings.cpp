// rad's derived settings (see rad_settings.h): RADIANCE 5.4 rad.c's renderopts,
// lowqopts/medqopts/hiqopts, pfiltopts, specview and getview.
#include "rad/rad_settings.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "util/options.h"

namespace rp::rad {

namespace {

constexpr double kTiny = 1e-6;  // RADIANCE's FTINY

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

[[noreturn]] void badValue(const RifVars& vars, Var v) {
    throw InputError(vars.where(v), std::string("bad value for variable '") + info(v).name + "'");
}

// addarg(): a space, then the words.
void addArg(std::string& s, const std::string& words) { s += ' ' + words; }

// The value after its first word (RADIANCE's sskip2(value, 1)).
std::string afterFirstWord(const std::string& s) {
    std::size_t i = 0;
    while (i < s.size() && isSpace(s[i])) ++i;
    while (i < s.size() && !isSpace(s[i])) ++i;
    while (i < s.size() && isSpace(s[i])) ++i;
    return s.substr(i);
}

std::string firstWord(const std::string& s) {
    std::size_t i = 0;
    while (i < s.size() && isSpace(s[i])) ++i;
    std::size_t j = i;
    while (j < s.size() && !isSpace(s[j])) ++j;
    return s.substr(i, j - i);
}

// Zone sizes and the octree cube over their mean, as the quality settings scale -ar.
struct ZoneScale {
    double sum = 0;       // dx + dy + dz
    double meanSize = 0;  // sum / 3
};
ZoneScale zoneScale(const RifVars& vars) {
    const Zone z = zoneOf(vars);
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
        const double d = z.max[i] - z.min[i];
        if (d <= kTiny) badValue(vars, Var::kZone);
        sum += d;
    }
    return {sum, sum / 3.};
}

// Low, medium and high DETAIL columns of one quality's table.
struct DetailRow {
    const char* pixelSample;  // -ps with penumbras
    const char* pixelSampleSharp;
    const char* directPretest;  // -dp
    int ambientResolution;      // -ar multiplier
    double maxSampleDivisor;    // -ms = mean zone size / this (0: no -ms)
};

struct QualityTable {
    DetailRow detail[3];
    const char* pixelTolerance;
    const char* directPenumbra;
    const char* directSharp;
    const char* directRest;
    const char* ambient[3];  // by VARIABILITY
    const char* limits;
};

// RADIANCE's lowqopts, medqopts and hiqopts as tables.
const QualityTable kLow{{{"-ps 16", "-ps 16", "-dp 64", 8, 0},
                         {"-ps 8", "-ps 8", "-dp 128", 16, 0},
                         {"-ps 4", "-ps 4", "-dp 256", 32, 0}},
                        "-pt .16",
                        "-ds .4",
                        "-ds 0",
                        "-dt .2 -dc .25 -dr 0 -ss 0 -st .5",
                        {"-aa .3 -ad 256", "-aa .25 -ad 512", "-aa .2 -ad 1024"},
                        "-lr 6 -lw .003"};
const QualityTable kMedium{
    {{"-ps 4", "-ps 8", "-dp 256", 16, 20},
     {"-ps 3", "-ps 6", "-dp 512", 32, 40},
     {"-ps 2", "-ps 4", "-dp 1024", 64, 80}},
    "-pt .08",
    "-ds .2 -dj .9",
    "-ds .3",
    "-dt .1 -dc .5 -dr 1 -ss 1 -st .1",
    {"-aa .2 -ad 329 -as 42", "-aa .15 -ad 800 -as 128", "-aa .1 -ad 1536 -as 392"},
    "-lr 8 -lw 1e-4"};
const QualityTable kHigh{
    {{"-ps 1", "-ps 8", "-dp 1024", 32, 40},
     {"-ps 1", "-ps 5", "-dp 2048", 64, 80},
     {"-ps 1", "-ps 3", "-dp 4096", 128, 160}},
    "-pt .04",
    "-ds .1 -dj .9",
    "-ds .2",
    "-dt .05 -dc .75 -dr 3 -ss 16 -st .01",
    {"-aa .125 -ad 512 -as 64", "-aa .1 -ad 1536 -as 768", "-aa .075 -ad 4096 -as 2048"},
    "-lr 12 -lw 1e-5"};

int levelIndex(char letter) { return letter == 'L' ? 0 : letter == 'M' ? 1 : 2; }

// One quality's options, appended to `op` (rendering) and `po` (picture).
void qualityOptions(const RifVars& vars, double cubeSize, std::string& op, std::string& po,
                    bool& overture) {
    const char q = vars.letter(Var::kQuality);
    const QualityTable& t = q == 'L' ? kLow : q == 'M' ? kMedium : kHigh;
    const ZoneScale zs = zoneScale(vars);
    // Low quality scales by 3/(dx+dy+dz), the others divide by the mean size: the same
    // number but for rounding, which -ar's truncation can show.
    const double d = q == 'L' ? cubeSize * (3. / zs.sum) : cubeSize / zs.meanSize;
    const bool penumbras = vars.isTrue(Var::kPenumbras);
    const DetailRow& row = t.detail[levelIndex(vars.letter(Var::kDetail))];
    addArg(po, penumbras ? row.pixelSample : row.pixelSampleSharp);
    addArg(op, row.directPretest);
    op += formatLine(" -ar %d", int(row.ambientResolution * d));
    if (row.maxSampleDivisor > 0) op += formatLine(" -ms %.2g", zs.meanSize / row.maxSampleDivisor);
    addArg(po, t.pixelTolerance);
    addArg(op, penumbras ? t.directPenumbra : t.directSharp);
    addArg(op, t.directRest);
    overture = false;
    if (q == 'M' && (overture = std::atoi(vars.value(Var::kIndirect).c_str()) != 0))
        op += formatLine(" -ab %d", std::atoi(vars.value(Var::kIndirect).c_str()));
    if (q == 'H') {
        const int ab = std::atoi(vars.value(Var::kIndirect).c_str()) + 1;
        overture = ab != 0;
        op += formatLine(" -ab %d", ab);
    }
    if (vars.defined(Var::kAmbFile))
        op += " -af " + vars.value(Var::kAmbFile);
    else
        overture = false;
    addArg(op, t.ambient[levelIndex(vars.letter(Var::kVariability))]);
    if (q == 'L') addArg(op, "-as 0");
    const double av = ambientValue(vars);
    op += formatLine(" -av %.2g %.2g %.2g", av, av, av);
    addArg(op, t.limits);
}

// " -ap file [bwidth]" for a PGMAP or PCMAP value "file nphotons [bwidth]".
std::string photonMapOption(const std::string& value) {
    const std::string bw = afterFirstWord(afterFirstWord(value));
    std::string s = " -ap " + firstWord(value);
    if (std::atoi(bw.c_str()) > 0) s += ' ' + bw;
    return s;
}

}  // namespace

Zone zoneOf(const RifVars& vars) {
    Zone z;
    z.type = vars.letter(Var::kZone);
    const std::string& s = vars.value(Var::kZone);
    if (std::sscanf(s.c_str(), "%*s %lf %lf %lf %lf %lf %lf", &z.min[0], &z.max[0], &z.min[1],
                    &z.max[1], &z.min[2], &z.max[2]) != 6)
        badValue(vars, Var::kZone);
    return z;
}

std::string toolOptions(const RifVars& vars, Var var, std::string& program) {
    if (!vars.defined(var)) return "";
    const std::string& v = vars.value(var);
    if (v[0] != '-') {
        program = firstWord(v);
        return ' ' + afterFirstWord(v);
    }
    return ' ' + v;
}

std::string parallelToolOptions(const RifVars& vars, Var var, int nprocs, std::string& program) {
    std::string s = nprocs > 1 ? formatLine(" -n %d", nprocs) : "";
    return s + toolOptions(vars, var, program);
}

double ambientValue(const RifVars& vars) {
    if (vars.defined(Var::kExposure)) {
        const std::string& e = vars.value(Var::kExposure);
        const double x = std::atof(e.c_str());
        if (e[0] == '+' || e[0] == '-') return .18 / std::pow(2., x);
        return .18 / x;
    }
    if (vars.letter(Var::kZone) == 'E') return 10.;
    if (vars.letter(Var::kZone) == 'I') return .01;
    badValue(vars, Var::kZone);
}

RenderSettings renderSettings(const RifVars& vars, double cubeSize, bool forRvu,
                              Programs& programs) {
    RenderSettings s;
    if (vars.defined(Var::kPgmap)) s.render = photonMapOption(vars.value(Var::kPgmap));
    qualityOptions(vars, cubeSize, s.render, s.picture, s.overture);
    if (vars.defined(Var::kPcmap)) s.render += photonMapOption(vars.value(Var::kPcmap));
    if (vars.defined(Var::kRender)) {
        const std::string& r = vars.value(Var::kRender);
        addArg(s.render, r);
        const std::size_t aa = r.find("-aa ");
        if (aa != std::string::npos && std::atof(r.c_str() + aa + 4) <= kTiny) s.overture = false;
    }
    if (forRvu)
        s.picture += toolOptions(vars, Var::kRvu, programs.rvu);
    else
        s.picture += toolOptions(vars, Var::kRpict, programs.rpict);
    return s;
}

std::string pfiltOptions(const RifVars& vars, Programs& programs) {
    std::string po;
    if (vars.defined(Var::kExposure)) {
        addArg(po, "-1 -e");
        addArg(po, vars.value(Var::kExposure));
    }
    if (vars.letter(Var::kQuality) == 'M') addArg(po, "-r .6");
    if (vars.letter(Var::kQuality) == 'H') addArg(po, "-m .25");
    return po + toolOptions(vars, Var::kPfilt, programs.pfilt);
}

namespace {

// The up axis from UP: 1, 2, 3 for X, Y, Z, negative for -X..., 0 when unset.
int upAxis(const RifVars& vars) {
    if (!vars.defined(Var::kUp)) return 0;
    const std::string& u = vars.value(Var::kUp);
    int ax = (u[0] == '-' || u[0] == '+') ? 1 - 'X' + (u.size() > 1 ? (u[1] & ~0x20) : 0)
                                          : 1 - 'X' + vars.letter(Var::kUp);
    if (ax < 1 || ax > 3) badValue(vars, Var::kUp);
    return u[0] == '-' ? -ax : ax;
}

constexpr const char* kUpVectors[7] = {"-vu 0 0 -1", "-vu 0 -1 0", "-vu -1 0 0", "-vu 0 0 1",
                                       "-vu 1 0 0",  "-vu 0 1 0",  "-vu 0 0 1"};

// A standard view ("X", "xZ", "XYZl", ...) around the zone: position, direction, up, size.
std::string standardView(const RifVars& vars, const int pos[3], char type, int upax) {
    const Zone z = zoneOf(vars);
    double cent[3], dim[3];
    for (int i = 0; i < 3; ++i) {
        dim[i] = z.max[i] - z.min[i];
        if (dim[i] <= kTiny) badValue(vars, Var::kZone);
        cent[i] = z.min[i] + .5 * dim[i];
    }
    const double mult = z.type == 'E' ? 2. : .45;
    std::string s = std::string("-vt") + type;
    s += formatLine(" -vp %.3g %.3g %.3g -vd %.3g %.3g %.3g", cent[0] + pos[0] * mult * dim[0],
                    cent[1] + pos[1] * mult * dim[1], cent[2] + pos[2] * mult * dim[2],
                    -pos[0] * dim[0], -pos[1] * dim[1], -pos[2] * dim[2]);
    // An up axis along the view direction is replaced.
    if (upax == 3 || upax == -3 || upax == 0) {
        if (!(pos[0] | pos[1])) upax = 2;
    } else if (upax == 2 || upax == -2) {
        if (!(pos[0] | pos[2])) upax = 1;
    } else if (!(pos[1] | pos[2])) {
        upax = 3;
    }
    addArg(s, kUpVectors[upax + 3]);
    if (type == 'v') {
        addArg(s, "-vh 45 -vv 45");
    } else if (type == 'l') {
        const double d = std::sqrt(dim[0] * dim[0] + dim[1] * dim[1] + dim[2] * dim[2]);
        s += formatLine(" -vh %.3g -vv %.3g", d, d);
    } else if (type == 'a' || type == 'h' || type == 's') {
        addArg(s, "-vh 180 -vv 180");
    } else if (type == 'c') {
        addArg(s, "-vh 180 -vv 90");
    }
    return s;
}

}  // namespace

std::optional<std::string> viewOptions(const RifVars& vars, const std::string& spec) {
    if (spec.empty() || spec[0] == '-') return spec;
    const int upax = upAxis(vars);
    int pos[3] = {0, 0, 0};
    std::size_t i = 0;
    const char axes[3] = {'X', 'Y', 'Z'};
    for (int a = 0; a < 3; ++a) {
        if (i < spec.size() && spec[i] == axes[a])
            pos[a] = 1, ++i;
        else if (i < spec.size() && spec[i] == (axes[a] | 0x20))
            pos[a] = -1, ++i;
    }
    char type = 'v';
    if (i < spec.size() && std::string("vlahsc").find(spec[i]) != std::string::npos)
        type = spec[i++];
    std::string out;
    if ((i >= spec.size() || isSpace(spec[i])) && (pos[0] | pos[1] | pos[2])) {
        out = standardView(vars, pos, type, upax);
    } else {
        i = 0;  // a name: skip it
        while (i < spec.size() && !isSpace(spec[i])) ++i;
        if (i >= spec.size()) return std::nullopt;
        if (upax) out = kUpVectors[upax + 3];
    }
    std::string rest = spec.substr(i);
    if (out.empty() && !rest.empty()) rest.erase(0, 1);  // no prefixed space needed
    return out + rest;
}

namespace {

// RADIANCE's matchword: the first word of `a` equals `b`'s first word.
bool sameFirstWord(const std::string& a, const std::string& b) {
    return firstWord(a) == firstWord(b) && !firstWord(a).empty();
}

bool isIntegerWord(const std::string& s) {
    std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
    if (i >= s.size()) return false;
    for (; i < s.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
    return true;
}

}  // namespace

std::optional<std::string> selectView(const RifVars& vars, const std::string* select, int n,
                                      std::string* name) {
    if (select && !select->empty()) {
        if (n) return std::nullopt;  // only one
        if (!isIntegerWord(*select)) {
            if ((*select)[0] == '-') {
                if (name) *name = "0";
                return *select;
            }
            if (name) *name = firstWord(*select);
            for (std::size_t k = 0; const Assignment* a = vars.nth(Var::kViews, k); ++k)
                if (sameFirstWord(*select, a->value)) return viewOptions(vars, a->value);
            return viewOptions(vars, *select);  // a standard view
        }
        n = std::atoi(select->c_str()) - 1;
    }
    const Assignment* a = n >= 0 ? vars.nth(Var::kViews, std::size_t(n)) : nullptr;
    if (!a) return std::nullopt;
    if (name) *name = a->value[0] != '-' ? firstWord(a->value) : std::to_string(n + 1);
    return viewOptions(vars, a->value);
}

}  // namespace rp::rad
