// Scene text writer (see xform_format.h). Layouts follow the printf formats of RADIANCE's
// src/gen/xform.c type by type, so that our xform output compares equal to RADIANCE's.
#include "gen/xform_format.h"

#include <cctype>
#include <cstdio>

namespace rp {

namespace {
std::string printfReal(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// " v0 v1 v2" from rargs[first..first+count), each " %18.12g".
std::string reals(const std::vector<double>& r, size_t first, size_t count) {
    std::string s;
    for (size_t i = first; i < first + count && i < r.size(); ++i) s += " " + formatReal(r[i]);
    return s;
}

std::string stringLine(const Primitive& p) {
    std::string s = std::to_string(p.sargs.size());
    for (const std::string& a : p.sargs) s += " " + formatWord(a);
    return s + "\n";
}

// RADIANCE compat: xform prints "0" for the integer count (it is built without IARGS);
// integer arguments, which no RADIANCE type takes, are still written if a record has them.
std::string integerLine(const Primitive& p) {
    std::string s = std::to_string(p.iargs.size());
    for (long v : p.iargs) s += " " + std::to_string(v);
    return s + "\n";
}

std::string realCount(const Primitive& p) { return std::to_string(p.rargs.size()); }

// o_default/addxform: all reals on the count line.
std::string defaultReals(const Primitive& p) {
    return realCount(p) + reals(p.rargs, 0, p.rargs.size()) + "\n";
}

// "N\n" then lines of `perLine` reals (each " %18.12g"), any remainder on a last line.
std::string linesOf(const Primitive& p, const std::initializer_list<size_t>& lines) {
    std::string s = realCount(p) + "\n";
    size_t at = 0;
    for (size_t n : lines) {
        if (at >= p.rargs.size()) break;
        s += reals(p.rargs, at, n) + "\n";
        at += n;
    }
    if (at < p.rargs.size()) s += reals(p.rargs, at, p.rargs.size() - at) + "\n";
    return s;
}

std::string shortReals(const std::vector<double>& r, size_t first, size_t count, const char* sep) {
    std::string s;
    for (size_t i = first; i < first + count && i < r.size(); ++i)
        s += (i == first ? std::string(sep) : std::string(" ")) + formatShortReal(r[i]);
    return s;
}

std::string realLines(const Primitive& p) {
    const auto& r = p.rargs;
    switch (p.type) {
        case PrimType::Source:
        case PrimType::Sphere:
        case PrimType::Bubble:
        case PrimType::Glow:
            return defaultReals(p);
        case PrimType::Polygon: {
            std::string s = realCount(p) + "\n";
            for (size_t i = 0; i + 3 <= r.size(); i += 3) s += reals(r, i, 3) + "\n";
            if (r.size() % 3) s += reals(r, r.size() - r.size() % 3, r.size() % 3) + "\n";
            return s;
        }
        case PrimType::Cone:
        case PrimType::Cup:
        case PrimType::Ring:
            return linesOf(p, {3, 3, 2});
        case PrimType::Cylinder:
        case PrimType::Tube:
            return linesOf(p, {3, 3, 1});
        case PrimType::Spotlight:
            if (r.size() != 7) return defaultReals(p);
            // xform.c m_spot(): the direction goes on a tab-indented line, no leading space.
            return realCount(p) + reals(r, 0, 4) + "\n\t" + formatReal(r[4]) + " " +
                   formatReal(r[5]) + " " + formatReal(r[6]) + "\n";
        case PrimType::Mist:
            return realCount(p) + shortReals(r, 0, r.size(), " ") + "\n";
        case PrimType::Dielectric:
            return realCount(p) + shortReals(r, 0, r.size(), " ") + "\n";
        case PrimType::Interface:
            if (r.size() != 8) return realCount(p) + shortReals(r, 0, r.size(), " ") + "\n";
            // xform.c m_interface(): two lines of four, no leading space.
            return realCount(p) + "\n" + shortReals(r, 0, 4, "") + "\n" + shortReals(r, 4, 4, "") +
                   "\n";
        case PrimType::Colortext:
        case PrimType::Brighttext:
        case PrimType::Mixtext: {
            // xform.c text(): anchor, right and down vectors on lines of three, then the
            // remaining reals continuing in lines of three.
            std::string s = realCount(p) + "\n";
            for (size_t i = 0; i < r.size(); ++i) {
                if (i > 0 && i % 3 == 0) s += "\n";
                s += " " + formatReal(r[i]);
            }
            return s + "\n";
        }
        default:
            return defaultReals(p);
    }
}
}  // namespace

std::string formatWord(std::string_view w) {
    bool space = false;
    char quote = 0;
    for (char c : w) {
        if (std::isspace(static_cast<unsigned char>(c)))
            space = true;
        else if (c == '"')
            quote = '\'';
        else if (c == '\'')
            quote = '"';
    }
    if (w.empty()) quote = '"';  // an empty argument must survive a re-read
    if (!space && !quote) return std::string(w);
    if (!quote) quote = '"';
    return quote + std::string(w) + quote;
}

std::string formatReal(double v) { return printfReal("%18.12g", v); }
std::string formatShortReal(double v) { return printfReal("%12.6g", v); }

std::string formatPrimitive(const Primitive& p) {
    std::string s = formatWord(p.modifierName) + " " + std::string(primTypeName(p.type)) + " " +
                    formatWord(p.name) + "\n";
    if (p.type == PrimType::Alias)  // xform.c alias(): the aliased name on a tab line
        return s + "\t" + (p.sargs.empty() ? std::string() : p.sargs[0]) + "\n";
    if (p.type == PrimType::Mist) {
        // xform.c m_mist() writes the source names with plain " %s".
        s += std::to_string(p.sargs.size());
        for (const std::string& a : p.sargs) s += " " + a;
        s += "\n";
    } else {
        s += stringLine(p);
    }
    return s + integerLine(p) + realLines(p);
}

}  // namespace rp
