// radcompare's text comparison (see radcompare_impl.h): "ascii" data and header-less
// text word by word, numbers compared as reals within the tolerances.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include "image/radcompare_impl.h"

namespace rp::radcompare_detail {

namespace {

// The end of the integer or real that starts at s (after white space), or null: RADIANCE's
// iskip and fskip.
const char* skipInteger(const char* s) {
    while (isSpace(*s)) ++s;
    s += (*s == '-') | (*s == '+');
    if (!isDigit(*s)) return nullptr;
    while (isDigit(*s)) ++s;
    return s;
}

const char* skipReal(const char* s) {
    while (isSpace(*s)) ++s;
    s += (*s == '-') | (*s == '+');
    const char* cp = s;
    while (isDigit(*cp)) ++cp;
    if (*cp == '.') {
        ++cp;
        ++s;
        while (isDigit(*cp)) ++cp;
    }
    if (cp == s) return nullptr;
    if (*cp == 'e' || *cp == 'E') return isSpace(*++cp) ? nullptr : skipInteger(cp);
    return cp;
}

const char* skipWord(const char* s) {
    while (isSpace(*s)) ++s;
    while (*s && !isSpace(*s)) ++s;
    return s;
}

}  // namespace

bool Comparer::equivalent(const char* s1, const char* s2) {
    while (isSpace(*s1)) ++s1;
    while (isSpace(*s2)) ++s2;
    while (*s1) {
        if (!*s2) return false;
        const char quote = (*s1 == '\'' || *s1 == '"') ? *s1 : '\0';
        if (quote) {  // quoted text must match exactly
            if (*s1++ != *s2++) return false;
            while (*s1 != quote) {
                if (!*s1 || *s1++ != *s2++) return false;
            }
            ++s1;
            if (*s2++ != quote) return false;
        } else {
            const char* w1 = s1;
            const char* w2 = s2;
            s1 = skipWord(s1);
            s2 = skipWord(s2);
            bool real = false;
            if (skipInteger(w1) == s1) {
                real = skipInteger(w2) != s2 && skipReal(w2) == s2;
            } else if (skipReal(w1) == s1) {
                if (skipReal(w2) != s2) return false;
                real = true;
            }
            if (real) {
                if (!realCheck(std::atof(std::string(w1, s1).c_str()),
                               std::atof(std::string(w2, s2).c_str())))
                    return false;
            } else if (s1 - w1 != s2 - w2 || std::strncmp(w1, w2, s1 - w1) != 0) {
                return false;
            }
        }
        while (isSpace(*s1)) ++s1;
        while (isSpace(*s2)) ++s2;
    }
    return !*s2;
}

namespace {

// Reads lines as RADIANCE's read_line, a comment line (-c#) becoming empty.
class LineReader {
public:
    LineReader(const Input& in, char comment)
        : d_(*in.bytes), pos_(in.dataStart), comment_(comment) {}
    bool next(std::string& line) {
        if (pos_ >= d_.size()) {
            line.clear();
            return false;
        }
        size_t nl = d_.find('\n', pos_);
        size_t end = nl == std::string::npos ? d_.size() : nl + 1;
        line.assign(d_, pos_, end - pos_);
        pos_ = end;
        if (comment_) {
            size_t k = 0;
            while (k < line.size() && isSpace(line[k])) ++k;
            if (k < line.size() && line[k] == comment_) line = line.substr(0, k) + "\n";
        }
        return true;
    }

private:
    const std::string& d_;
    size_t pos_;
    char comment_;
};

bool blank(const std::string& s) {
    for (char c : s)
        if (!isSpace(c)) return false;
    return true;
}

}  // namespace

bool Comparer::compareText(Input& a, Input& b) {
    if (verbose()) {
        out_ << prog_ << ": comparing inputs as ASCII text";
        if (opt_.comment) out_ << ", ignoring comments starting with '" << opt_.comment << '\'';
        out_ << '\n';
    }
    LineReader r1(a, opt_.comment), r2(b, opt_.comment);
    std::string l1, l2;
    int n1 = a.lines, n2 = b.lines;
    while (r1.next(l1)) {
        ++n1;
        if (blank(l1)) continue;
        bool got = false;
        while (r2.next(l2)) {
            ++n2;
            if (!blank(l2)) {
                got = true;
                break;
            }
        }
        if (!got) {
            if (reports()) out_ << b.name << ": unexpected end-of-file\n";
            return false;
        }
        if (!equivalent(l1.c_str(), l2.c_str())) {
            if (reports()) {
                out_ << prog_ << ": inputs '" << a.name << "' and '" << b.name
                     << "' differ at line " << n1 << '|' << n2 << '\n';
                if (verbose() && l1.size() < 256 && l2.size() < 256) {
                    out_ << "------------- Mismatch -------------\n";
                    out_ << a.name << '@' << n1 << ":\t" << l1;
                    out_ << b.name << '@' << n2 << ":\t" << l2;
                }
            }
            return false;
        }
    }
    while (r2.next(l2)) {
        if (blank(l2)) continue;
        if (reports()) out_ << a.name << ": unexpected end-of-file\n";
        return false;
    }
    return goodRms(a, b);
}

}  // namespace rp::radcompare_detail
