// Text helpers for the generators: printf-style formatting, header line, number parsing,
// option tables.
#include "gen/gen_text.h"

#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <optional>

#include "util/error.h"

namespace rp::gen {

std::string cformat(const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    va_list ap2;
    va_copy(ap2, ap);
    int n = std::vsnprintf(nullptr, 0, fmt, ap);
    va_end(ap);
    std::string out(n > 0 ? static_cast<size_t>(n) : 0, '\0');
    if (n > 0) std::vsnprintf(out.data(), out.size() + 1, fmt, ap2);
    va_end(ap2);
    return out;
}

std::string headerWord(const std::string& word) {
    // RADIANCE compat (fputword.c): a word with white space is put in double quotes; a
    // quote character inside the word (not first, not last) selects the other kind of
    // quote, the last such character deciding.
    bool space = false;
    char quote = 0;
    for (size_t i = 0; i < word.size(); ++i) {
        char c = word[i];
        if (std::isspace(static_cast<unsigned char>(c)))
            space = true;
        else if (i > 0 && i + 1 < word.size() && (c == '"' || c == '\''))
            quote = c == '"' ? '\'' : '"';
    }
    if (!space && !quote) return word;
    if (!quote) quote = '"';
    return quote + word + quote;
}

std::string commandHeader(const std::vector<std::string>& args, bool quoteWords) {
    std::string out = "#";
    for (const std::string& a : args) {
        out += ' ';
        out += quoteWords ? headerWord(a) : a;
    }
    out += '\n';
    return out;
}

std::string vertexLine(const Vec3& p) {
    return cformat("\t%18.12g\t%18.12g\t%18.12g\n", p.x, p.y, p.z);
}

double parseReal(const std::string& word, const std::string& what) {
    const std::optional<double> v = rp::parseReal(word);
    if (!v) throw InputError("bad " + what + " '" + word + "': expected a number");
    return *v;
}

int parseInt(const std::string& word, const std::string& what) {
    const std::optional<long> v = rp::parseInteger(word);
    if (!v || *v < -1000000000L || *v > 1000000000L)
        throw InputError("bad " + what + " '" + word + "': expected an integer");
    return static_cast<int>(*v);
}

OptionTable genOptionTable() {
    OptionTable t;
    t.defaultsStops = false;
    t.messages.missing = [](const std::string& opt) { return "option " + opt + " needs a value"; };
    t.messages.unknown = [](const std::string& opt) { return "unknown option '" + opt + "'"; };
    return t;
}

OptionSpec realOption(const std::string& name, const std::string& what,
                      std::function<void(double)> set) {
    return customOption(
        name, [what, set = std::move(set)](OptionReader& r) { set(parseReal(r.word(), what)); });
}

OptionSpec intOption(const std::string& name, const std::string& what,
                     std::function<void(int)> set) {
    return customOption(
        name, [what, set = std::move(set)](OptionReader& r) { set(parseInt(r.word(), what)); });
}

OptionSpec wordOption(const std::string& name, std::function<void()> set) {
    return customOption(name, [set = std::move(set)](OptionReader&) { set(); });
}

}  // namespace rp::gen
