// JSON out, query values in (see web_json.h).
#include "rvu/web_json.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace rp::rvu {

namespace {

// Length of the valid UTF-8 sequence at s[i], or 0 (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF).
size_t utf8Length(const std::string& s, size_t i) {
    auto byte = [&](size_t k) { return static_cast<unsigned char>(s[i + k]); };
    const unsigned c = byte(0);
    if (c < 0x80) return 1;
    size_t n = 0;
    unsigned lo = 0x80, hi = 0xbf;  // the allowed range of the second byte
    if (c >= 0xc2 && c <= 0xdf) {
        n = 2;
    } else if (c >= 0xe0 && c <= 0xef) {
        n = 3;
        if (c == 0xe0) lo = 0xa0;
        if (c == 0xed) hi = 0x9f;
    } else if (c >= 0xf0 && c <= 0xf4) {
        n = 4;
        if (c == 0xf0) lo = 0x90;
        if (c == 0xf4) hi = 0x8f;
    } else {
        return 0;
    }
    if (i + n > s.size() || byte(1) < lo || byte(1) > hi) return 0;
    for (size_t k = 2; k < n; ++k)
        if ((byte(k) & 0xc0) != 0x80) return 0;
    return n;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c < 0x20 || c == 0x7f) {
            out += fmt::format("\\u{:04x}", c);
        } else if (c >= 0x80) {
            const size_t n = utf8Length(s, i);
            out += n ? s.substr(i, n) : "\\ufffd";
            i += n ? n : 1;
            continue;
        } else {
            out += char(c);
        }
        ++i;
    }
    return out + "\"";
}

void JsonObject::key(const std::string& k) {
    if (!body_.empty()) body_ += ',';
    body_ += jsonString(k) + ':';
}

void JsonObject::add(const std::string& k, const std::string& value) {
    key(k);
    body_ += jsonString(value);
}

void JsonObject::add(const std::string& k, double value) {
    key(k);
    body_ += std::isfinite(value) ? fmt::format("{}", value) : "null";
}

void JsonObject::add(const std::string& k, bool value) {
    key(k);
    body_ += value ? "true" : "false";
}

std::string commandJson(const CommandResult& r) {
    JsonObject j;
    j.add("ok", r.ok);
    if (!r.output.empty() || r.ok) j.add("output", r.output);
    if (!r.error.empty()) j.add("error", r.error);
    if (!r.pick.empty()) {
        j.add("pick", r.pick);
        j.add("points", double(r.points));
    }
    if (r.quit) j.add("quit", true);
    return j.text();
}

std::string errorJson(const std::string& message) {
    JsonObject j;
    j.add("ok", false);
    j.add("error", message);
    return j.text();
}

uint64_t parseGeneration(const std::string& s) {
    // Digits only: strtoull alone would take " -1" as 2^64 - 1 (a ten-second wait).
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) return 0;
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
    if (*end || errno) return 0;
    return v;
}

bool parseCursor(const std::string& s, std::vector<Cursor>& out) {
    std::vector<long> values;
    const char* p = s.c_str();
    while (*p) {
        if (!isDigit(*p == '-' ? p[1] : *p)) return false;  // no blanks, no '+'
        char* end = nullptr;
        errno = 0;
        const long v = std::strtol(p, &end, 10);
        if (end == p || errno || v < -1000000 || v > 1000000) return false;
        values.push_back(v);
        p = end;
        if (*p == ',') {
            ++p;
            if (!*p) return false;
        } else if (*p) {
            return false;
        }
    }
    if (values.size() != 2 && values.size() != 4) return false;
    out.clear();
    for (size_t i = 0; i < values.size(); i += 2)
        out.push_back({int(values[i]), int(values[i + 1])});
    return true;
}

}  // namespace rp::rvu
