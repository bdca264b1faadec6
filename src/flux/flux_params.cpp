// `#@rfluxmtx` settings (see flux_params.h).
#include "flux/flux_params.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace rp::flux {

namespace {

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

// The word at `i` (to white space or the end), advancing `i` past it.
std::string wordAt(const std::string& s, size_t& i) {
    const size_t start = i;
    while (i < s.size() && !isSpace(s[i])) ++i;
    return s.substr(start, i - start);
}

// h=[+|-]spec: RADIANCE keeps every character of spec and reads the basis size from all
// of its digits together ("r4" is MF 4, "sc12" is 12 by 12).
bool readHemisphere(const std::string& s, size_t& i, FluxParams& p) {
    char sign = '+';
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) sign = s[i++];
    const std::string spec = wordAt(s, i);
    if (spec.empty()) return false;
    p.sign = sign;
    p.hemis = spec;
    p.size = 0;
    for (char c : spec)
        if (std::isdigit(static_cast<unsigned char>(c))) p.size = 10 * p.size + (c - '0');
    if (p.size == 0) p.size = 1;
    return true;
}

// o=name, o="name with spaces" or o='...'.
bool readOutput(const std::string& s, size_t& i, FluxParams& p) {
    char quote = 0;
    if (i < s.size() && (s[i] == '"' || s[i] == '\'')) quote = s[i++];
    const size_t start = i;
    while (i < s.size() && (quote ? s[i] != quote : !isSpace(s[i]))) ++i;
    if (i == start || (quote && i == s.size())) return false;
    p.outSpec = s.substr(start, i - start);
    if (quote) ++i;
    return true;
}

}  // namespace

std::optional<Vec3> parseUpDirection(const std::string& text) {
    double sign = 1;
    size_t i = 0;
    for (; i < text.size() && (text[i] == '+' || text[i] == '-'); ++i)
        if (text[i] == '-') sign = -sign;
    const std::string rest = text.substr(i);
    if (rest.size() == 1 && std::string("xyzXYZ").find(rest[0]) != std::string::npos) {
        Vec3 v;
        const char axis = lower(rest[0]);
        (axis == 'x' ? v.x : axis == 'y' ? v.y : v.z) = sign;
        return v;
    }
    double c[3];
    const char* s = rest.c_str();
    for (int k = 0; k < 3; ++k) {
        char* end = nullptr;
        c[k] = std::strtod(s, &end);
        if (end == s) return std::nullopt;
        s = end;
        if (k < 2 && *s++ != ',') return std::nullopt;
    }
    // RADIANCE compat (rfluxmtx.c get_direction): a leading '-' negates only the x
    // component of a vector ("-0,0,1" is +Z), while it reverses an axis letter.
    Vec3 v{c[0] * sign, c[1], c[2]};
    const double len = length(v);
    if (!(len > 0) || !std::isfinite(len)) return std::nullopt;
    return v / len;
}

std::optional<BasisKind> basisOf(const std::string& h) {
    const char h0 = h.empty() ? '\0' : lower(h[0]);
    const char h1 = h.size() > 1 ? lower(h[1]) : '\0';
    if (h0 == 'u' || h0 == '1') return BasisKind::Uniform;
    if (h0 == 's' && h1 == 'c') return BasisKind::ShirleyChiu;
    if (h0 == 'r' || h0 == 't') return BasisKind::Reinhart;
    if (h0 != 'k') return std::nullopt;
    if (h1 == '\0' || h1 == 'f' || h1 == '1') return BasisKind::KlemsFull;
    if (h1 == 'h' || h1 == '2') return BasisKind::KlemsHalf;
    if (h1 == 'q' || h1 == '4') return BasisKind::KlemsQuarter;
    return std::nullopt;
}

void applyParamLine(const std::string& text, const SourceLoc& loc, FluxParams& p) {
    std::string shown = text;
    while (!shown.empty() && isSpace(shown.back())) shown.pop_back();
    while (!shown.empty() && isSpace(shown.front())) shown.erase(0, 1);
    const InputError bad(loc, "bad parameter string: " + shown);
    size_t i = 0;
    while (true) {
        while (i < text.size() && isSpace(text[i])) ++i;
        if (i >= text.size()) return;
        const char key = text[i];
        if (i + 1 >= text.size() || text[i + 1] != '=') throw bad;
        i += 2;
        if (key == 'h') {
            if (!readHemisphere(text, i, p)) throw bad;
            p.hemisLoc = loc;
            if (!basisOf(p.hemis))
                throw InputError(loc, "unrecognized hemisphere sampling: h=" + p.hemis);
        } else if (key == 'u') {
            const std::optional<Vec3> up = parseUpDirection(wordAt(text, i));
            if (!up) throw bad;
            p.up = *up;
        } else if (key == 'o') {
            if (!readOutput(text, i, p)) throw bad;
        } else {
            throw bad;
        }
    }
}

}  // namespace rp::flux
