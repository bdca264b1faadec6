// RIF variables (see rif.h): RADIANCE 5.4's loadvars.c semantics.
#include "rad/rif.h"

#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>

#include "util/warnings.h"

namespace rp::rad {

namespace {

// RADIANCE's table (rad.c vv[]): name, characters needed to abbreviate, kind.
constexpr std::array<VarInfo, kVarCount> kVars{{
    {"AMBFILE", 3, VarKind::kOne},     {"DETAIL", 3, VarKind::kQuality},
    {"EXPOSURE", 3, VarKind::kFloat},  {"EYESEP", 3, VarKind::kFloat},
    {"illum", 3, VarKind::kCat},       {"INDIRECT", 3, VarKind::kInt},
    {"materials", 3, VarKind::kCat},   {"mkillum", 3, VarKind::kCat},
    {"mkpmap", 3, VarKind::kCat},      {"objects", 3, VarKind::kCat},
    {"oconv", 3, VarKind::kCat},       {"OCTREE", 3, VarKind::kOne},
    {"OPTFILE", 3, VarKind::kOne},     {"PCMAP", 2, VarKind::kOne},
    {"PENUMBRAS", 3, VarKind::kBool},  {"pfilt", 2, VarKind::kCat},
    {"PGMAP", 2, VarKind::kOne},       {"PICTURE", 3, VarKind::kOne},
    {"QUALITY", 3, VarKind::kQuality}, {"RAWFILE", 3, VarKind::kOne},
    {"render", 3, VarKind::kCat},      {"REPORT", 3, VarKind::kOne},
    {"RESOLUTION", 3, VarKind::kOne},  {"rpict", 3, VarKind::kCat},
    {"rvu", 3, VarKind::kCat},         {"scene", 3, VarKind::kCat},
    {"UP", 2, VarKind::kOne},          {"VARIABILITY", 3, VarKind::kQuality},
    {"view", 2, VarKind::kList},       {"ZFILE", 2, VarKind::kOne},
    {"ZONE", 2, VarKind::kOne},
}};

// A backslash-escaped character: dropped from values (RADIANCE's NOCHAR).
constexpr char kNoChar = 127;

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
char upper(char c) { return static_cast<char>(c & ~0x20); }  // RADIANCE's UPPER

// RADIANCE's fgetline: a line, continued while its newline follows a backslash (both
// stay in the text); "\r\n" and a lone '\r' end lines too.
bool readLine(std::istream& in, std::string& line, int& newlines) {
    line.clear();
    newlines = 0;
    int c = EOF;
    while ((c = in.get()) != EOF) {
        if (c == '\r') {
            if (in.peek() == '\n') in.get();
            c = '\n';
        }
        if (c == '\n') {
            ++newlines;
            if (line.empty() || line.back() != '\\') break;
        }
        line.push_back(static_cast<char>(c));
    }
    return !(line.empty() && c == EOF);
}

// loadvars(): a backslash escapes the next character; '#' starts a comment.
void stripLine(std::string& line) {
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '\\') {
            line[i++] = kNoChar;
        } else if (line[i] == '#') {
            line.resize(i);
            break;
        }
    }
}

// RADIANCE's badmatch: `value` (any case) is a prefix of `word`.
bool prefixOf(const std::string& value, const char* word) {
    if (value.empty() || value.size() > std::strlen(word)) return false;
    for (std::size_t i = 0; i < value.size(); ++i)
        if (upper(value[i]) != word[i]) return false;
    return true;
}

// RADIANCE's iskip/fskip: an integer, or a real without spaces, filling the string.
bool isInteger(const std::string& s) {
    std::size_t i = 0;
    while (i < s.size() && isSpace(s[i])) ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    const std::size_t digits = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i > digits && i == s.size();
}

bool isReal(const std::string& s) {
    std::size_t i = 0;
    while (i < s.size() && isSpace(s[i])) ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    bool digits = false;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, digits = true;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, digits = true;
    }
    if (!digits) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E'))
        return isInteger(s.substr(i + 1)) && !isSpace(s[i + 1]);
    return i == s.size();
}

const char* legalityWord(VarKind kind) {
    switch (kind) {
        case VarKind::kQuality:
            return "qualitative";
        case VarKind::kBool:
            return "boolean";
        case VarKind::kInt:
            return "integer";
        case VarKind::kFloat:
            return "real";
        default:
            return "";
    }
}

bool legal(VarKind kind, const std::string& v) {
    switch (kind) {
        case VarKind::kQuality:
            return prefixOf(v, "LOW") || prefixOf(v, "MEDIUM") || prefixOf(v, "HIGH");
        case VarKind::kBool:
            return prefixOf(v, "TRUE") || prefixOf(v, "FALSE");
        case VarKind::kInt:
            return isInteger(v);
        case VarKind::kFloat:
            return isReal(v);
        default:
            return true;
    }
}

// setvariable()'s value: runs of white space squeezed to their first character,
// escaped characters dropped, no trailing space.
std::string squeezed(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == kNoChar) continue;
        if (isSpace(c) && (out.empty() || isSpace(out.back()))) continue;
        out.push_back(c);
    }
    if (!out.empty() && isSpace(out.back())) out.pop_back();
    return out;
}

}  // namespace

const VarInfo& info(Var v) { return kVars[static_cast<std::size_t>(v)]; }

bool matchVar(const std::string& name, Var& out) {
    for (std::size_t i = 0; i < kVarCount; ++i) {
        const VarInfo& vi = kVars[i];
        if (int(name.size()) >= vi.nick && name.size() <= std::strlen(vi.name) &&
            name.compare(0, name.size(), vi.name, name.size()) == 0) {
            out = static_cast<Var>(i);
            return true;
        }
    }
    return false;
}

std::vector<std::string> valueWords(const std::string& value) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (true) {
        while (i < value.size() && isSpace(value[i])) ++i;
        if (i >= value.size()) break;
        char quote = 0;
        if (value[i] == '"' || value[i] == '\'') quote = value[i++];
        std::string w;
        while (i < value.size() && (quote ? value[i] != quote : !isSpace(value[i])))
            w.push_back(value[i++]);
        if (quote && i < value.size()) ++i;
        words.push_back(w);
    }
    return words;
}

void RifVars::load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, "cannot open rad input file");
    load(in, path);
}

void RifVars::load(std::istream& in, const std::string& path) {
    std::string line;
    int lineNo = 1, newlines = 0;
    while (readLine(in, line, newlines)) {
        stripLine(line);
        if (!assign(line, SourceLoc{path, lineNo}))
            throw InputError(SourceLoc{path, lineNo}, "unknown variable: " + squeezed(line));
        lineNo += newlines;
    }
}

bool RifVars::assign(const std::string& text, const SourceLoc& loc) {
    std::size_t i = 0;
    while (i < text.size() && isSpace(text[i])) ++i;
    std::string name;
    while (i < text.size() && name.size() < 31 && !isSpace(text[i]) && text[i] != '=')
        name.push_back(text[i++]);
    if (name.empty()) return true;
    while (i < text.size() && (isSpace(text[i]) || text[i] == '=')) ++i;
    const std::string value = squeezed(text.substr(i));
    if (value.empty()) return true;  // RADIANCE: a name without a value assigns nothing
    Var v;
    if (!matchVar(name, v)) return false;
    vars_[index(v)].push_back({value, loc});
    return true;
}

void RifVars::check(bool warnings) {
    for (std::size_t i = 0; i < kVarCount; ++i) {
        std::vector<Assignment>& a = vars_[i];
        const VarInfo& vi = kVars[i];
        if (a.empty() || vi.kind == VarKind::kList) continue;
        if (vi.kind == VarKind::kCat) {
            joined_[i] = a[0].value;
            for (std::size_t k = 1; k < a.size(); ++k) joined_[i] += ' ' + a[k].value;
            continue;
        }
        if (a.size() > 1) {
            if (warnings) warn(std::string("multiple assignment of variable '") + vi.name + "'");
            a.erase(a.begin(), a.end() - 1);
        }
        if (!legal(vi.kind, a[0].value))
            throw InputError(a[0].loc, std::string("illegal value for ") + legalityWord(vi.kind) +
                                           " variable '" + vi.name + "'");
    }
}

const std::string& RifVars::value(Var v) const {
    static const std::string kEmpty;
    const auto& a = vars_[index(v)];
    if (a.empty()) return kEmpty;
    return info(v).kind == VarKind::kCat && !joined_[index(v)].empty() ? joined_[index(v)]
                                                                       : a[0].value;
}

const Assignment* RifVars::nth(Var v, std::size_t n) const {
    const auto& a = vars_[index(v)];
    return n < a.size() ? &a[n] : nullptr;
}

const SourceLoc& RifVars::where(Var v) const {
    static const SourceLoc kNone;
    const auto& a = vars_[index(v)];
    return a.empty() ? kNone : a[0].loc;
}

char RifVars::letter(Var v) const {
    const std::string& s = value(v);
    return s.empty() ? '\0' : upper(s[0]);
}

void RifVars::setDefault(Var v, const std::string& value) {
    if (!defined(v)) vars_[index(v)].push_back({value, SourceLoc{}});
}

// printvars(): lines of a joined list break after 64 characters (less the name) at the
// end of a word and go on with "NAME="; other values break after 236 with " \".
std::string RifVars::listing() const {
    std::ostringstream out;
    for (std::size_t i = 0; i < kVarCount; ++i) {
        const VarInfo& vi = kVars[i];
        const bool cat = vi.kind == VarKind::kCat;
        const int clip = (cat ? 64 : 236) - int(std::strlen(vi.name));
        for (std::size_t n = 0; n < vars_[i].size(); ++n) {
            if (cat && n > 0) break;  // joined
            out << vi.name << "= ";
            int k = clip;
            const std::string& s = cat ? value(static_cast<Var>(i)) : vars_[i][n].value;
            for (std::size_t c = 0; c < s.size();) {
                out << s[c++];
                if (--k > 0) continue;
                while (c < s.size() && !isSpace(s[c])) out << s[c++];
                if (c < s.size()) {
                    if (cat)
                        out << '\n' << vi.name << '=';
                    else
                        out << " \\\n";
                    k = clip;
                }
            }
            out << '\n';
        }
    }
    return out.str();
}

}  // namespace rp::rad
