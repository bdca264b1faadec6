// RADIANCE view options and view rays (see view.h). Formulas follow RADIANCE's
// image.c (setview, viewray) and the -vt section of rpict.1.
#include "image/view.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

#include "util/error.h"

namespace rp {

namespace {

constexpr double kTiny = 1e-6;  // RADIANCE's FTINY

bool parseNumber(const char* s, double& v) {
    char* end;
    v = std::strtod(s, &end);
    return end != s && *end == '\0' && std::isfinite(v);
}

// Reads n numbers after the option at argv[0]; throws naming the option.
void numbers(int argc, const char* const* argv, int n, double* out) {
    if (argc - 1 < n)
        throw InputError(std::string(argv[0]) + ": expected " + std::to_string(n) +
                         (n == 1 ? " number" : " numbers"));
    for (int i = 0; i < n; ++i)
        if (!parseNumber(argv[1 + i], out[i]))
            throw InputError(std::string(argv[0]) + ": bad number '" + argv[1 + i] + "'");
}

bool validType(char c) {
    switch (c) {
        case 'v':
        case 'l':
        case 'c':
        case 'h':
        case 'a':
        case 's':
            return true;
        default:
            return false;
    }
}

int parseOption(View& v, int argc, const char* const* argv, bool allowFile) {
    if (argc <= 0) return 0;
    const std::string opt = argv[0];
    if (opt.size() < 3 || opt[0] != '-' || opt[1] != 'v') return 0;
    if (opt[2] == 't') {
        if (opt.size() != 4 || !validType(opt[3]))
            throw InputError("-vt: unknown view type '" + opt.substr(3) +
                             "' (expected one of vlchas)");
        v.type = static_cast<ViewType>(opt[3]);
        return 1;
    }
    if (opt.size() != 3) return 0;
    double x[3];
    auto vec = [&](Vec3& out) {
        numbers(argc, argv, 3, x);
        out = {x[0], x[1], x[2]};
        return 4;
    };
    auto one = [&](double& out) {
        numbers(argc, argv, 1, x);
        out = x[0];
        return 2;
    };
    switch (opt[2]) {
        case 'p':
            return vec(v.point);
        case 'd':
            return vec(v.direction);
        case 'u':
            return vec(v.up);
        case 'h':
            return one(v.horizontal);
        case 'v':
            return one(v.vertical);
        case 'o':
            return one(v.fore);
        case 'a':
            return one(v.aft);
        case 's':
            return one(v.shift);
        case 'l':
            return one(v.lift);
        case 'f':
            if (!allowFile) return 0;
            if (argc < 2) throw InputError("-vf: expected a file name");
            readViewFile(v, argv[1]);
            return 2;
        default:
            return 0;
    }
}

int applyWords(View& view, const std::string& text, bool allowFile) {
    std::istringstream ss(text);
    std::vector<std::string> words;
    for (std::string w; ss >> w;) words.push_back(w);
    std::vector<const char*> argv;
    for (const auto& w : words) argv.push_back(w.c_str());
    int n = 0;
    const int argc = static_cast<int>(argv.size());
    for (int i = 0; i < argc;) {
        int used = parseOption(view, argc - i, argv.data() + i, allowFile);
        if (used > 0) {
            ++n;
            i += used;
        } else {
            ++i;
        }
    }
    return n;
}

}  // namespace

// RADIANCE compat: isview() in image.c: header lines that carry views start with
// VIEW= or a rendering program's command line.
bool isViewLine(const std::string& line) {
    if (line.rfind("VIEW=", 0) == 0) return true;
    std::string first = line.substr(0, line.find_first_of(" \t"));
    size_t slash = first.find_last_of('/');
    if (slash != std::string::npos) first = first.substr(slash + 1);
    for (const char* prog : {"rpict", "rview", "rvu", "rpiece", "pinterp"})
        if (first.rfind(prog, 0) == 0) return true;
    return false;
}

namespace {

std::string fmt(const char* f, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, a);
    return buf;
}

std::string fmt3(const char* opt, const Vec3& v) {
    char buf[128];
    std::snprintf(buf, sizeof buf, " %s %.6g %.6g %.6g", opt, v.x, v.y, v.z);
    return buf;
}

bool feq(double a, double b) { return std::fabs(a - b) <= kTiny; }
bool veq(const Vec3& a, const Vec3& b) { return feq(a.x, b.x) && feq(a.y, b.y) && feq(a.z, b.z); }

}  // namespace

OptionSpec viewOptionSpec(View& view) {
    auto matches = [](const std::string& w) {
        return w.size() >= 3 && w.rfind("-v", 0) == 0 &&
               (w[2] == 't' ||
                (w.size() == 3 && std::string("pduhvoaslf").find(w[2]) != std::string::npos));
    };
    return customOption(matches, "-v", [&view](OptionReader& r) {
        const size_t at = r.next() - 1;  // the option word itself
        std::vector<const char*> words;
        for (size_t k = at; k < r.args().size(); ++k) words.push_back(r.args()[k].c_str());
        const int n = parseViewOption(view, int(words.size()), words.data());
        if (n <= 0) throw InputError("unknown option '" + r.option() + "'");  // not reached
        r.skipTo(at + size_t(n));
    });
}

int parseViewOption(View& view, int argc, const char* const* argv) {
    return parseOption(view, argc, argv, true);
}

int applyViewString(View& view, const std::string& text) { return applyWords(view, text, false); }

std::optional<View> viewFromHeader(const Header& header) {
    View v;
    int n = 0;
    for (const auto& line : header.lines)
        if (isViewLine(line)) n += applyWords(v, line, false);
    if (n == 0) return std::nullopt;
    return v;
}

void readViewFile(View& view, const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, "cannot open view file");
    Header h;
    View v = view;
    int n = 0;
    try {
        if (tryReadHeader(in, h)) {
            for (const auto& line : h.lines)
                if (isViewLine(line)) n += applyWords(v, line, false);
        } else {
            in.clear();
            in.seekg(0);
            std::string line;
            for (int lineNo = 1; std::getline(in, line); ++lineNo) {
                if (line.size() > 4096) break;  // not a text file
                if (!line.empty() && line[0] == '#') continue;
                try {
                    n += applyWords(v, line, false);
                } catch (const InputError& e) {
                    throw InputError(SourceLoc{path, lineNo}, e.message());
                }
            }
        }
    } catch (const InputError& e) {
        if (!e.loc().file.empty()) throw;
        throw InputError(SourceLoc{path, 0}, e.message());
    }
    if (n == 0) throw InputError(SourceLoc{path, 0}, "no view parameters in file");
    view = v;
}

std::string formatView(const View& v) {
    std::string s = " -vt";
    s += static_cast<char>(v.type);
    s += fmt3("-vp", v.point) + fmt3("-vd", v.direction) + fmt3("-vu", v.up);
    s += fmt(" -vh %.6g", v.horizontal) + fmt(" -vv %.6g", v.vertical);
    s += fmt(" -vo %.6g", v.fore) + fmt(" -va %.6g", v.aft);
    s += fmt(" -vs %.6g", v.shift) + fmt(" -vl %.6g", v.lift);
    return s;
}

std::string formatViewMinimal(const View& v) {
    const View d;
    std::string s;
    if (v.type != d.type) {
        s += " -vt";
        s += static_cast<char>(v.type);
    }
    if (!veq(v.point, d.point)) s += fmt3("-vp", v.point);
    if (!veq(v.direction, d.direction)) s += fmt3("-vd", v.direction);
    if (!veq(v.up, d.up)) s += fmt3("-vu", v.up);
    if (!feq(v.horizontal, d.horizontal)) s += fmt(" -vh %.6g", v.horizontal);
    if (!feq(v.vertical, d.vertical)) s += fmt(" -vv %.6g", v.vertical);
    if (!feq(v.fore, d.fore)) s += fmt(" -vo %.6g", v.fore);
    if (!feq(v.aft, d.aft)) s += fmt(" -va %.6g", v.aft);
    if (!feq(v.shift, d.shift)) s += fmt(" -vs %.6g", v.shift);
    if (!feq(v.lift, d.lift)) s += fmt(" -vl %.6g", v.lift);
    return s;
}

std::string viewHeaderLine(const View& view) { return "VIEW=" + formatView(view); }

ImagePlaneSize imagePlaneSize(const View& v) {
    const double degHalf = kPi / 360.0;  // degrees to radians, halved
    ImagePlaneSize p;
    switch (v.type) {
        case ViewType::kParallel:
            p = {v.horizontal, v.vertical};
            break;
        case ViewType::kPerspective:
            p = {2 * std::tan(v.horizontal * degHalf), 2 * std::tan(v.vertical * degHalf)};
            break;
        case ViewType::kCylindrical:
            p = {v.horizontal * (kPi / 180), 2 * std::tan(v.vertical * degHalf)};
            break;
        case ViewType::kAngular:
            p = {v.horizontal * (kPi / 180), v.vertical * (kPi / 180)};
            break;
        case ViewType::kHemispherical:
            p = {2 * std::sin(v.horizontal * degHalf), 2 * std::sin(v.vertical * degHalf)};
            break;
        case ViewType::kPlanisphere:
            p = {2 * std::sin(v.horizontal * degHalf) / (1 + std::cos(v.horizontal * degHalf)),
                 2 * std::sin(v.vertical * degHalf) / (1 + std::cos(v.vertical * degHalf))};
            break;
    }
    return p;
}

ViewRays::ViewRays(const View& v) : view_(v) {
    const char* illHoriz = "illegal horizontal view size";
    const char* illVert = "illegal vertical view size";
    if (v.fore < -kTiny || v.aft < -kTiny || (v.aft > kTiny && v.aft <= v.fore))
        throw InputError("illegal fore/aft clipping plane");
    focalDistance_ = length(v.direction);
    if (focalDistance_ == 0) throw InputError("zero view direction");
    dir_ = v.direction / focalDistance_;
    if (length(v.up) == 0) throw InputError("zero view up vector");
    hvec_ = cross(dir_, normalize(v.up));
    // RADIANCE only rejects an exactly zero cross product; nearly parallel vectors
    // give a meaningless image orientation, so we reject those too.
    if (length(hvec_) <= kTiny) throw InputError("view up parallel to view direction");
    hvec_ = normalize(hvec_);
    vvec_ = cross(hvec_, dir_);
    if (v.horizontal <= kTiny) throw InputError(illHoriz);
    if (v.vertical <= kTiny) throw InputError(illVert);
    switch (v.type) {
        case ViewType::kParallel:
            break;
        case ViewType::kPerspective:
            if (v.horizontal >= 180 - kTiny) throw InputError(illHoriz);
            if (v.vertical >= 180 - kTiny) throw InputError(illVert);
            break;
        case ViewType::kCylindrical:
            if (v.horizontal > 360 + kTiny) throw InputError(illHoriz);
            if (v.vertical >= 180 - kTiny) throw InputError(illVert);
            break;
        case ViewType::kAngular:
            if (v.horizontal > 360 + kTiny) throw InputError(illHoriz);
            if (v.vertical > 360 + kTiny) throw InputError(illVert);
            break;
        case ViewType::kHemispherical:
            if (v.horizontal > 180 + kTiny) throw InputError(illHoriz);
            if (v.vertical > 180 + kTiny) throw InputError(illVert);
            break;
        case ViewType::kPlanisphere:
            if (v.horizontal >= 360 - kTiny) throw InputError(illHoriz);
            if (v.vertical >= 360 - kTiny) throw InputError(illVert);
            break;
        default:
            throw InputError("unknown view type");
    }
    const ImagePlaneSize plane = imagePlaneSize(v);
    const double hn = plane.horizontal, vn = plane.vertical;
    // RADIANCE compat (setview): the image-plane vectors carry the plane size except
    // where viewray works in angles (a, s; and horizontally for c).
    if (v.type != ViewType::kAngular && v.type != ViewType::kPlanisphere) {
        if (v.type != ViewType::kCylindrical) hvec_ *= hn;
        vvec_ *= vn;
    }
    hn2_ = hn * hn;
    vn2_ = vn * vn;
}

std::optional<ViewRays::Ray> ViewRays::ray(double x, double y) const {
    const View& v = view_;
    x += v.shift - 0.5;
    y += v.lift - 0.5;
    Ray r;
    // Distance limit for types whose direction was not normalised from a longer vector.
    const double aftPlain = v.aft > kTiny ? v.aft - v.fore : 0.0;
    Vec3 d;
    switch (v.type) {
        case ViewType::kParallel:
            r.origin = v.point + v.fore * dir_ + x * hvec_ + y * vvec_;
            r.direction = dir_;
            r.maxDistance = aftPlain;
            return r;
        case ViewType::kPerspective:
        case ViewType::kCylindrical: {
            if (v.type == ViewType::kPerspective) {
                d = dir_ + x * hvec_ + y * vvec_;
            } else {
                double a = x * v.horizontal * (kPi / 180);
                d = std::cos(a) * dir_ + std::sin(a) * hvec_ + y * vvec_;
            }
            // The fore plane is a plane, not a sphere: offset along the unnormalised
            // direction, and scale the aft distance the same way.
            r.origin = v.point + v.fore * d;
            double len = length(d);
            r.direction = d / len;
            r.maxDistance = v.aft > kTiny ? (v.aft - v.fore) * len : 0.0;
            return r;
        }
        case ViewType::kHemispherical: {
            double z = 1 - x * x * hn2_ - y * y * vn2_;
            if (z < 0) return std::nullopt;
            d = std::sqrt(z) * dir_ + x * hvec_ + y * vvec_;
            break;
        }
        case ViewType::kAngular: {
            x *= v.horizontal / 180;
            y *= v.vertical / 180;
            double r2 = x * x + y * y;
            if (r2 > 1) return std::nullopt;
            double rad = std::sqrt(r2);
            double z = std::cos(kPi * rad);
            double s = rad <= kTiny ? kPi : std::sqrt(1 - z * z) / rad;
            d = z * dir_ + (x * s) * hvec_ + (y * s) * vvec_;
            break;
        }
        case ViewType::kPlanisphere: {
            x *= std::sqrt(hn2_);
            y *= std::sqrt(vn2_);
            double r2 = x * x + y * y;
            double z = (1 - r2) / (1 + r2);
            d = z * dir_ + (x * (1 + z)) * hvec_ + (y * (1 + z)) * vvec_;
            break;
        }
        default:
            return std::nullopt;
    }
    // Fisheye directions are unit length by construction; the fore clip is a sphere.
    r.origin = v.point + v.fore * d;
    r.direction = normalize(d);
    r.maxDistance = aftPlain;
    return r;
}

bool ViewRays::locateFisheye(const Vec3& dir, Location& loc) const {
    const View& v = view_;
    loc.x = 0.5 - v.shift;
    loc.y = 0.5 - v.lift;
    const double d = dot(dir, dir_);
    if (d >= 1 - kTiny) return true;  // straight ahead: the centre
    if (v.type == ViewType::kAngular) {
        if (d <= -(1 - kTiny)) {  // straight behind: the circle's edge
            loc.x += 180 / v.horizontal;
            return true;
        }
        // Image radius proportional to the angle off the view direction.
        const double s = (180 / kPi) * std::acos(d) / std::sqrt(1 - d * d);
        loc.x += dot(dir, hvec_) * s / v.horizontal;
        loc.y += dot(dir, vvec_) * s / v.vertical;
        return true;
    }
    if (d <= -(1 - kTiny)) return false;  // the planisphere's pole
    loc.x += dot(dir, hvec_) / ((1 + d) * std::sqrt(hn2_));
    loc.y += dot(dir, vvec_) / ((1 + d) * std::sqrt(vn2_));
    return true;
}

std::optional<ViewRays::Location> ViewRays::locate(const Vec3& p) const {
    const View& v = view_;
    const bool aftClip = v.aft > kTiny;
    Vec3 disp = p - v.point;
    Location loc;
    bool plane = true;  // x and y from the image-plane vectors (types v, l, h)
    switch (v.type) {
        case ViewType::kParallel:
            loc.depth = dot(disp, dir_) - v.fore;
            break;
        case ViewType::kPerspective: {
            double d = dot(disp, dir_);
            loc.beyond = aftClip && d >= v.aft;
            loc.depth = length(disp);
            // RADIANCE compat (viewloc): a point behind the view is mirrored through it
            // (the pyramid folded back) and flagged behind by a negative depth.
            if (d < -kTiny) {
                loc.depth = -loc.depth;
                d = -d;
            } else if (d <= kTiny) {
                return std::nullopt;  // in the plane of the view point
            }
            disp *= 1 / d;  // onto the image plane one unit ahead
            // ray() starts at the fore plane: the depth is what lies past it.
            loc.depth *= 1 - v.fore / (loc.depth < 0 ? -d : d);
            break;
        }
        case ViewType::kHemispherical: {
            const double len = length(disp);
            if (len == 0) return std::nullopt;
            disp *= 1 / len;
            loc.depth = (dot(disp, dir_) < 0 ? -len : len) - v.fore;
            break;
        }
        case ViewType::kCylindrical: {
            const double across = dot(disp, hvec_), ahead = dot(disp, dir_);
            const double r2 = across * across + ahead * ahead;
            if (r2 <= kTiny * kTiny) return std::nullopt;  // on the panorama's axis
            loc.beyond = aftClip && r2 >= v.aft * v.aft;
            const double inv = 1 / std::sqrt(r2);
            loc.x = (180 / kPi) * std::atan2(across, ahead) / v.horizontal + 0.5 - v.shift;
            loc.y = dot(disp, vvec_) * inv / vn2_ + 0.5 - v.lift;
            loc.depth = length(disp) * (1 - v.fore * inv);
            plane = false;
            break;
        }
        case ViewType::kAngular:
        case ViewType::kPlanisphere: {
            const double len = length(disp);
            if (len == 0) return std::nullopt;
            loc.depth = len - v.fore;
            if (!locateFisheye(disp * (1 / len), loc)) return std::nullopt;
            plane = false;
            break;
        }
        default:
            return std::nullopt;
    }
    if (plane) {
        loc.x = dot(disp, hvec_) / hn2_ + 0.5 - v.shift;
        loc.y = dot(disp, vvec_) / vn2_ + 0.5 - v.lift;
    }
    if (loc.depth <= 0) {
        loc.behind = true;
    } else if (v.type != ViewType::kPerspective && v.type != ViewType::kCylindrical) {
        loc.beyond = aftClip && loc.depth >= v.aft - v.fore;
    }
    loc.outside = !(loc.x > 0 && loc.x < 1 && loc.y > 0 && loc.y < 1);
    return loc;
}

namespace {

// Shirley & Chiu's concentric map ("A Low Distortion Map Between Disk and Square",
// J. Graphics Tools 2(3), 1997): uniform on the square to uniform on the unit disk,
// keeping strata compact.
std::pair<double, double> squareToDisk(double u1, double u2) {
    const double a = 2 * u1 - 1, b = 2 * u2 - 1;
    if (a == 0 && b == 0) return {0, 0};
    double r, phi;
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = (kPi / 4) * (b / a);
    } else {
        r = b;
        phi = kPi / 2 - (kPi / 4) * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

}  // namespace

bool ViewRays::jitterAperture(Ray& ray, double diameter, double u1, double u2, double u3) const {
    if (diameter <= kTiny) return true;
    auto [dx, dy] = squareToDisk(u1, u2);
    dx *= 0.5 * diameter;
    dy *= 0.5 * diameter;
    // The aperture lies in the plane of the view's right and up directions, whatever
    // lengths hvec_/vvec_ carry for this view type.
    Vec3 shift = dx * normalize(hvec_) + dy * normalize(vvec_);
    Vec3 focus;
    switch (view_.type) {
        case ViewType::kPerspective:
            // The focal surface is the plane at the focal distance, as RADIANCE's.
            focus = view_.point + (focalDistance_ / dot(ray.direction, dir_)) * ray.direction;
            break;
        case ViewType::kParallel:
            // Not RADIANCE: its jitteraperture aims every parallel ray at the single
            // point vp + vdist * vdir, which folds the picture onto that point. We focus
            // each ray on its own point at the focal distance from the view plane.
            focus = ray.origin + (focalDistance_ - view_.fore) * dir_;
            break;
        default:
            // RADIANCE compat (jitteraperture): a focal sphere, and an extra random shift
            // along the view direction for the views that bend rays sideways.
            focus = view_.point + focalDistance_ * ray.direction;
            shift += (kPi / 4 * diameter * (0.5 - u3)) * dir_;
            break;
    }
    ray.origin += shift;
    const Vec3 d = focus - ray.origin;
    const double len = length(d);
    if (len == 0) return false;
    ray.direction = d / len;
    return true;
}

}  // namespace rp
