// Scanning sender and receiver files (see flux_scan.h).
#include "flux/flux_scan.h"

#include <sys/wait.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "gen/builtin_commands.h"
#include "scene/lexer.h"
#include "util/file_read.h"
#include "util/warnings.h"

namespace rp::flux {

namespace {

constexpr double kFtiny = 1e-6;  // RADIANCE's FTINY
constexpr int kMaxCommandDepth = 32;

// Runs a `!command` of a sender or receiver file: our generators in-process, anything
// else through /bin/sh as RADIANCE's popen.
std::string commandOutput(const std::string& command, const SourceLoc& loc) {
    if (std::optional<std::string> out = gen::runBuiltinCommand(command, loc)) return *out;
    std::fflush(nullptr);  // keep our buffered output ahead of the child's
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) throw InputError(loc, "cannot load '!" + command + "'");
    std::string text;
    char buf[65536];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) text.append(buf, n);
    const int status = ::pclose(pipe);
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw InputError(loc, "error loading '!" + command + "'");
    return text;
}

// Normal and area of a polygon from the fan of its vertices (rfluxmtx.c finish_polygon).
void finishPolygon(FluxSurface& s) {
    const size_t nv = s.args.size() / 3;
    auto vertex = [&](size_t i) {
        return Vec3{s.args[3 * i], s.args[3 * i + 1], s.args[3 * i + 2]};
    };
    Vec3 sum;
    Vec3 e1 = vertex(1) - vertex(0);
    for (size_t i = 2; i < nv; ++i) {
        const Vec3 e2 = vertex(i) - vertex(0);
        sum = sum + cross(e1, e2);
        e1 = e2;
    }
    const double len = length(sum);
    s.normal = len > 0 ? sum / len : Vec3{};
    s.area = 0.5 * len;
}

// The normal and area rfluxmtx.c add_surface derives; false for a zero orientation.
bool finishSurface(FluxSurface& s) {
    std::vector<double>& a = s.args;
    switch (s.type) {
        case SurfaceType::Polygon:
            finishPolygon(s);
            return true;
        case SurfaceType::Ring: {
            const Vec3 n{a[3], a[4], a[5]};
            if (length(n) == 0) return false;
            s.normal = normalize(n);
            if (a[7] < a[6]) std::swap(a[6], a[7]);
            s.area = kPi * (a[7] * a[7] - a[6] * a[6]);
            return true;
        }
        case SurfaceType::Source: {
            // The source's direction points at it; rays arrive travelling the other way.
            const Vec3 n{-a[0], -a[1], -a[2]};
            if (length(n) == 0) return false;
            s.normal = normalize(n);
            const double h = std::sin(kPi / 360 * a[3]);
            s.area = kPi * h * h;
            return true;
        }
    }
    return false;
}

std::optional<SurfaceType> surfaceType(const std::string& type) {
    if (type == "polygon") return SurfaceType::Polygon;
    if (type == "ring") return SurfaceType::Ring;
    if (type == "source") return SurfaceType::Source;
    return std::nullopt;
}

class Scanner {
public:
    Scanner(std::string_view text, std::string file, std::vector<ScanItem>& items, int depth,
            std::optional<SourceLoc> commandLoc)
        : lex_(text),
          file_(std::move(file)),
          items_(items),
          depth_(depth),
          commandLoc_(std::move(commandLoc)) {}

    void run();

private:
    SourceLoc loc(int line) const { return commandLoc_ ? *commandLoc_ : SourceLoc{file_, line}; }
    bool word(std::string& w) {
        int line;
        return lex_.readWord(w, line);
    }
    void comment();
    void command();
    void object();
    void readArgs(const std::string& name, const SourceLoc& at, std::vector<double>* reals);

    SceneLexer lex_;
    std::string file_;
    std::vector<ScanItem>& items_;
    int depth_;
    std::optional<SourceLoc> commandLoc_;  // where the command whose output this is stands
};

void Scanner::run() {
    while (lex_.skipSpace()) {
        const char c = lex_.peek();
        if (c == '#')
            comment();
        else if (c == '!')
            command();
        else
            object();
    }
}

// RADIANCE compat (rfluxmtx.c load_scene): `#` directly followed by the word
// `@rfluxmtx` carries settings for the rest of its line; any other comment is skipped.
void Scanner::comment() {
    const int line = lex_.line();
    std::string first;
    int l;
    lex_.readWord(first, l);  // '#' and what follows it up to white space
    if (first != "#@rfluxmtx") {
        lex_.skipComment();
        return;
    }
    ScanItem item;
    item.isParams = true;
    item.loc = loc(line);
    item.paramText = lex_.readCommand();  // the rest of the line, quotes and all
    items_.push_back(std::move(item));
}

void Scanner::command() {
    const SourceLoc at = loc(lex_.line());
    const std::string cmd = lex_.readCommand();
    if (depth_ >= kMaxCommandDepth) throw InputError(at, "commands nested too deeply: !" + cmd);
    const std::string out = commandOutput(cmd, at);
    Scanner(out, file_, items_, depth_ + 1, at).run();
}

void Scanner::readArgs(const std::string& name, const SourceLoc& at, std::vector<double>* reals) {
    const InputError bad(at, "error reading arguments for '" + name + "'");
    std::string w;
    for (int group = 0; group < 3; ++group) {
        long n = 0;
        if (!word(w) || !parseInteger(w, n) || n < 0) throw bad;
        for (long k = 0; k < n; ++k) {
            if (!word(w)) throw bad;
            double v = 0;
            if (group == 2 && !parseReal(w, v)) throw bad;
            if (group == 2 && reals) reals->push_back(v);
        }
    }
}

void Scanner::object() {
    const SourceLoc at = loc(lex_.line());
    std::string modifier, type, name;
    // RADIANCE stops at a primitive cut short by the end of the file.
    if (!word(modifier) || !word(type) || !word(name)) return;
    if (type == "alias") {
        word(name);
        return;
    }
    const std::optional<SurfaceType> st = surfaceType(type);
    if (!st) {
        readArgs(name, at, nullptr);
        return;
    }
    ScanItem item;
    item.loc = at;
    FluxSurface& s = item.surface;
    s.type = *st;
    s.modifier = modifier;
    s.name = name;
    s.loc = at;
    readArgs(name, at, &s.args);
    const size_t n = s.args.size();
    const bool countOk = *st == SurfaceType::Polygon ? n >= 9 && n % 3 == 0
                         : *st == SurfaceType::Ring  ? n == 8
                                                     : n == 4;
    if (!countOk) throw InputError(at, "bad argument count for surface element '" + name + "'");
    if (!finishSurface(s))
        throw InputError(at, "bad orientation for surface element '" + name + "'");
    // RADIANCE compat (rfluxmtx.c add_surface): a surface without area is left out with a
    // warning (RADIANCE keeps it under -w; it adds nothing either way).
    if (s.area <= kFtiny * kFtiny) {
        warn(at, "zero area for surface '" + name + "'");
        return;
    }
    items_.push_back(std::move(item));
}

}  // namespace

std::vector<ScanItem> scanFluxText(const std::string& text, const std::string& file) {
    std::vector<ScanItem> items;
    Scanner(text, file, items, 0, std::nullopt).run();
    return items;
}

std::vector<ScanItem> scanFluxFile(const std::string& path) {
    if (!path.empty() && path[0] == '!') {
        std::vector<ScanItem> items;
        const SourceLoc at{path, 0};
        Scanner(commandOutput(path.substr(1), at), path, items, 1, at).run();
        return items;
    }
    std::string text;
    try {
        text = readFileBytes(path);
    } catch (const InputError&) {
        throw InputError("cannot load '" + path + "'");
    }
    return scanFluxText(text, path);
}

}  // namespace rp::flux
