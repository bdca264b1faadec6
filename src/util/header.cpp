#include "util/header.h"

#include <cctype>
#include <ctime>

#include "util/error.h"

namespace rp {

namespace {
std::string lastValue(const std::vector<std::string>& lines, const std::string& key) {
    for (auto it = lines.rbegin(); it != lines.rend(); ++it)
        if (it->compare(0, key.size(), key) == 0) return it->substr(key.size());
    return {};
}

// Reads one '\n'-terminated line (without the '\n'); false at end of stream.
bool getLine(std::istream& in, std::string& line, bool& sawNewline) {
    line.clear();
    sawNewline = false;
    int c;
    while ((c = in.get()) != EOF) {
        if (c == '\n') {
            sawNewline = true;
            return true;
        }
        line.push_back(static_cast<char>(c));
        if (line.size() > 1 << 20) return false;  // not a text header
    }
    return !line.empty();
}
}  // namespace

std::string Header::format() const { return lastValue(lines, "FORMAT="); }

std::string Header::value(const std::string& name) const { return lastValue(lines, name + "="); }

bool tryReadHeader(std::istream& in, Header& out) {
    out.lines.clear();
    std::string line;
    bool nl;
    if (!getLine(in, line, nl) || !nl || line != kHeaderMagic) return false;
    while (getLine(in, line, nl)) {
        if (!nl) return false;
        if (line.empty()) return true;
        out.lines.push_back(line);
    }
    return false;
}

Header readHeader(std::istream& in, const std::string& what) {
    Header h;
    std::string line;
    bool nl;
    if (!getLine(in, line, nl) || line != kHeaderMagic)
        throw InputError(SourceLoc{what, 0}, "not a RADIANCE file (no #?RADIANCE header)");
    while (true) {
        if (!getLine(in, line, nl) || !nl)
            throw InputError(SourceLoc{what, 0}, "truncated header (no empty line ends it)");
        if (line.empty()) return h;
        h.lines.push_back(line);
    }
}

void writeHeader(std::ostream& out, const Header& h) {
    out << kHeaderMagic << '\n';
    for (const auto& l : h.lines) out << l << '\n';
    out << '\n';
}

std::string captureTimeLines() {
    const std::time_t now = std::time(nullptr);
    std::tm t{};
    char buf[80];
    std::string s;
    localtime_r(&now, &t);
    std::strftime(buf, sizeof buf, "CAPDATE= %Y:%m:%d %H:%M:%S\n", &t);
    s += buf;
    gmtime_r(&now, &t);
    std::strftime(buf, sizeof buf, "GMT= %Y:%m:%d %H:%M:%S\n", &t);
    return s + buf;
}

std::string commandLine(int argc, const char* const* argv) {
    std::string s;
    for (int i = 0; i < argc; ++i) {
        if (i) s += ' ';
        const std::string a = argv[i];
        bool space = false;
        char quote = 0;
        for (size_t k = 0; k < a.size(); ++k) {
            const char c = a[k];
            if (std::isspace(static_cast<unsigned char>(c)))
                space = true;
            else if (k > 0 && k + 1 < a.size() && c == '"')
                quote = '\'';
            else if (k > 0 && k + 1 < a.size() && c == '\'')
                quote = '"';
        }
        if (space || quote) {
            if (!quote) quote = '"';
            s += quote + a + quote;
        } else {
            s += a;
        }
    }
    return s;
}

}  // namespace rp
