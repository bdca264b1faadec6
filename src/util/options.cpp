// The option table (see options.h): value readers, matching rules, parsing, -defaults.
#include "util/options.h"

#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

#include "util/command_args.h"
#include "util/error.h"

namespace rp {

std::optional<uint64_t> parseCount(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || errno != 0) return std::nullopt;
    const std::string rest(end);
    if (rest == "k" || rest == "K")
        v *= 1e3;
    else if (rest == "m" || rest == "M")
        v *= 1e6;
    else if (rest == "g" || rest == "G")
        v *= 1e9;
    else if (!rest.empty())
        return std::nullopt;
    if (!(v >= 1) || v > 1e15) return std::nullopt;
    return uint64_t(std::llround(v));
}

std::optional<long> parseInteger(const std::string& s) {
    char* end = nullptr;
    errno = 0;
    const long n = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || end == s.c_str() || *end != '\0' || errno != 0) return std::nullopt;
    return n;
}

std::optional<double> parseReal(const std::string& s) {
    char* end = nullptr;
    const double d = std::strtod(s.c_str(), &end);
    if (s.empty() || end == s.c_str() || *end != '\0' || !std::isfinite(d)) return std::nullopt;
    return d;
}

const std::string& OptionReader::word() {
    if (at_ >= args_.size()) throw InputError(messages_.missing(opt_));
    return args_[at_++];
}

double OptionReader::real() {
    const std::string& v = word();
    const std::optional<double> d = parseReal(v);
    if (!d) bad(v, ValueKind::kReal);
    return *d;
}

long OptionReader::integer(long lo, long hi) {
    const std::string& v = word();
    const std::optional<long> n = parseInteger(v);
    if (!n || *n < lo || *n > hi) bad(v, ValueKind::kInteger);
    return *n;
}

uint64_t OptionReader::count() {
    const std::string& v = word();
    const std::optional<uint64_t> n = parseCount(v);
    if (!n) bad(v, ValueKind::kCount);
    return *n;
}

Color OptionReader::color() {
    Color c;
    for (int k = 0; k < 3; ++k) c[k] = real();
    return c;
}

bool OptionReader::nextIsInteger() const {
    return at_ < args_.size() && parseInteger(args_[at_]).has_value();
}

void OptionReader::bad(const std::string& value, ValueKind kind) const {
    throw InputError(messages_.bad(opt_, value, kind));
}

void OptionReader::require(bool ok, const std::string& what) const {
    if (!ok) throw InputError(messages_.range(opt_, what));
}

std::function<bool(const std::string&)> exactly(std::string name) {
    return [name = std::move(name)](const std::string& w) { return w == name; };
}

std::function<bool(const std::string&)> prefix(std::string name, size_t maxLength) {
    return [name = std::move(name), maxLength](const std::string& w) {
        return w.size() <= maxLength && w.rfind(name, 0) == 0;
    };
}

OptionSpec flagOption(const std::string& name, bool& value, size_t maxLength) {
    const size_t len = name.size();
    return {name,
            prefix(name, maxLength),
            [&value, len](OptionReader& r) { value = boolSuffix(r.option(), len, value); },
            {}};
}

OptionSpec valueOption(const std::string& name, std::string& v) {
    return {name, exactly(name), [&v](OptionReader& r) { v = r.word(); }, {}};
}

OptionSpec valueOption(const std::string& name, double& v, std::function<bool(double)> ok,
                       std::string what) {
    return {name,
            exactly(name),
            [&v, ok = std::move(ok), what = std::move(what)](OptionReader& r) {
                const double x = r.real();
                if (ok) r.require(ok(x), what);
                v = x;
            },
            {}};
}

OptionSpec valueOption(const std::string& name, int& v, std::function<bool(long)> ok,
                       std::string what) {
    return {name,
            exactly(name),
            [&v, ok = std::move(ok), what = std::move(what)](OptionReader& r) {
                const long x = r.integer();
                if (ok) r.require(ok(x), what);
                v = int(x);
            },
            {}};
}

OptionSpec countOption(const std::string& name, uint64_t& v) {
    return {name, exactly(name), [&v](OptionReader& r) { v = r.count(); }, {}};
}

OptionSpec valueOption(const std::string& name, Color& v) {
    return {name, exactly(name), [&v](OptionReader& r) { v = r.color(); }, {}};
}

OptionSpec customOption(const std::string& name, std::function<void(OptionReader&)> read) {
    return {name, exactly(name), std::move(read), {}};
}

OptionSpec customOption(std::function<bool(const std::string&)> matches, const std::string& name,
                        std::function<void(OptionReader&)> read) {
    return {name, std::move(matches), std::move(read), {}};
}

std::string formatLine(const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    va_list ap2;
    va_copy(ap2, ap);
    const int n = std::vsnprintf(nullptr, 0, fmt, ap);
    va_end(ap);
    std::string out(n > 0 ? size_t(n) : 0, '\0');
    if (n > 0) std::vsnprintf(out.data(), out.size() + 1, fmt, ap2);
    va_end(ap2);
    return out;
}

void OptionTable::add(OptionSpec spec, std::function<std::string()> defaults) {
    for (const OptionSpec& s : specs_)
        if (s.name == spec.name) return;
    if (defaults) spec.defaults = std::move(defaults);
    specs_.push_back(std::move(spec));
}

void OptionTable::setDefaults(const std::string& name, std::function<std::string()> defaults) {
    for (OptionSpec& s : specs_)
        if (s.name == name) {
            s.defaults = std::move(defaults);
            return;
        }
    throw std::logic_error("no option " + name + " in the table");
}

const OptionSpec* OptionTable::find(const std::string& word) const {
    for (const OptionSpec& s : specs_)
        if (s.matches(word)) return &s;
    return nullptr;
}

OptionParse OptionTable::parse(std::vector<std::string>& args, size_t first) const {
    size_t i = first;
    while (true) {
        // RADIANCE compat (expandarg): only option positions are expanded, never values.
        if (expandArgs) expandArgAt(args, i);
        if (i >= args.size()) return {i, OptionStop::kEnd};
        const std::string& w = args[i];
        if (w.size() < 2 || (w[0] != '-' && !(plusWords && w[0] == '+')))
            return {i, OptionStop::kEnd};
        if (w == "-version") return {i, OptionStop::kVersion};
        if (defaultsStops && (w == "-defaults" || (helpIsDefaults && w == "-help")))
            return {i, OptionStop::kDefaults};
        const OptionSpec* spec = find(w);
        if (!spec) {
            if (unknownEnds) return {i, OptionStop::kEnd};
            throw InputError(messages.unknown(w));
        }
        OptionReader reader(args, i, spec->messages ? *spec->messages : messages);
        spec->read(reader);
        i = reader.next();
    }
}

void OptionTable::parseAll(std::vector<std::string>& args, size_t first) const {
    const OptionParse p = parse(args, first);
    if (p.next < args.size()) throw InputError(messages.unknown(args[p.next]));
}

std::string OptionTable::formatDefaults() const {
    std::string out;
    if (defaultsOrder_.empty()) {
        for (const OptionSpec& s : specs_)
            if (s.defaults) out += s.defaults();
        return out;
    }
    for (const std::string& name : defaultsOrder_)
        for (const OptionSpec& s : specs_)
            if (s.name == name && s.defaults) out += s.defaults();
    return out;
}

}  // namespace rp
