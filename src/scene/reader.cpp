// Scene description reader (see reader.h). Follows RADIANCE's readobj.c/getobject():
// comments and commands only where a primitive could start, counts then arguments,
// modifiers looked up among earlier modifiers only.
#include "scene/reader.h"

#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "scene/arg_rules.h"
#include "scene/lexer.h"
#include "scene/modifier_table.h"
#include "util/file_read.h"
#include "util/warnings.h"

namespace rp {

namespace {
constexpr const char* kInherit = "inherit";  // ray.html, Scene Description: alias
constexpr const char* kVoidName = "void";

std::string describe(PrimType t, const std::string& name) {
    return std::string(primTypeName(t)) + " '" + name + "'";
}

std::string shorten(const std::string& s) { return s.size() <= 60 ? s : s.substr(0, 57) + "..."; }
}  // namespace

struct SceneReader::Context {
    std::string file;
    const SourceLoc* commandLoc = nullptr;  // set while reading a command's output
    int depth = 0;

    // Records from command output point at the command's line in the user's file.
    SourceLoc loc(int line) const { return commandLoc ? *commandLoc : SourceLoc{file, line}; }
};

SceneReader::SceneReader(LoadOptions options) : options_(std::move(options)) {}

int64_t fileMtime(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return 0;
    return static_cast<int64_t>(st.st_mtime);
}

void SceneReader::readFile(const std::string& path) {
    size_t before = scene_.prims.size();
    if (path == "-") {
        std::string text{std::istreambuf_iterator<char>(std::cin),
                         std::istreambuf_iterator<char>()};
        scene_.inputs.push_back({"-", 0});
        parse(text, Context{""});  // empty file name = standard input (util/error.h)
    } else if (!path.empty() && path[0] == '!') {
        runCommand(path.substr(1), SourceLoc{}, 1);
    } else {
        readContents(path, readFileBytes(path));
        return;
    }
    // RADIANCE compat: readobj() warns "(file): empty file".
    if (scene_.prims.size() == before) warn(SourceLoc{path == "-" ? "" : path, 0}, "empty file");
}

void SceneReader::readContents(const std::string& path, std::string_view text) {
    size_t before = scene_.prims.size();
    scene_.inputs.push_back({path, fileMtime(path)});
    parse(text, Context{path});
    if (scene_.prims.size() == before) warn(SourceLoc{path, 0}, "empty file");
}

void SceneReader::readText(std::string_view text, const std::string& file) {
    parse(text, Context{file});
}

void SceneReader::append(const Scene& other) {
    auto offset = static_cast<int32_t>(scene_.prims.size());
    for (Primitive p : other.prims) {
        if (p.modifier != kVoid) p.modifier += offset;
        if (p.aliasOf >= 0) p.aliasOf += offset;
        scene_.prims.push_back(std::move(p));
        index(static_cast<int32_t>(scene_.prims.size() - 1));
    }
    scene_.inputs.insert(scene_.inputs.end(), other.inputs.begin(), other.inputs.end());
}

void SceneReader::parse(std::string_view text, const Context& ctx) {
    SceneLexer lex(text);
    while (lex.skipSpace()) {
        char c = lex.peek();
        if (c == '#') {
            lex.skipComment();
        } else if (c == '!') {
            int line = lex.line();
            std::string command = lex.readCommand();
            runCommand(command, ctx.loc(line), ctx.depth + 1);
        } else {
            parsePrimitive(lex, ctx);
        }
    }
}

void SceneReader::runCommand(const std::string& rawCommand, const SourceLoc& loc, int depth) {
    std::string command = rawCommand;
    command.erase(0, command.find_first_not_of(" \t"));
    if (depth > options_.maxCommandDepth)
        throw InputError(loc, "commands nested too deeply: !" + shorten(command));
    std::optional<std::string> output;
    if (options_.commandHook) output = options_.commandHook(command, loc);
    if (!output) {
        std::fflush(nullptr);  // keep our buffered output ahead of the child's
        FILE* pipe = ::popen(command.c_str(), "r");  // popen runs /bin/sh -c command
        if (!pipe) throw InputError(loc, "cannot run command: !" + shorten(command));
        std::string text;
        char buf[65536];
        size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) text.append(buf, n);
        int status = ::pclose(pipe);
        // RADIANCE compat: readobj() only warns "bad status"; a failed generator leaves
        // a silently incomplete scene, so we stop instead.
        if (status == -1) throw InputError(loc, "cannot run command: !" + shorten(command));
        if (WIFSIGNALED(status))
            throw InputError(loc, "command killed by signal " + std::to_string(WTERMSIG(status)) +
                                      ": !" + shorten(command));
        if (WEXITSTATUS(status) != 0)
            throw InputError(loc, "command failed with exit status " +
                                      std::to_string(WEXITSTATUS(status)) + ": !" +
                                      shorten(command));
        output = std::move(text);
    }
    Context ctx{loc.file, &loc, depth};
    try {
        parse(*output, ctx);
    } catch (const InputError& e) {
        if (e.message().find(" (in output of !") != std::string::npos) throw;
        throw InputError(e.loc(), e.message() + " (in output of !" + shorten(command) + ")");
    }
}

int32_t SceneReader::resolveModifier(const std::string& name, const SourceLoc& loc) const {
    if (name == kVoidName) return kVoid;
    auto it = modifiers_.find(name);
    if (it != modifiers_.end()) return it->second;
    auto s = surfaces_.find(name);
    if (s != surfaces_.end())
        throw InputError(loc, "'" + name + "' is a " +
                                  std::string(primTypeName(scene_.prims[s->second].type)) +
                                  ", a surface, and cannot be used as a modifier");
    if (options_.geometryOnly) return kVoid;
    throw InputError(loc, "undefined modifier '" + name + "'");
}

void SceneReader::add(Primitive p) {
    if (!checkArgs(p) && !options_.radianceNumbering) return;  // degenerate, warned
    scene_.prims.push_back(std::move(p));
    index(static_cast<int32_t>(scene_.prims.size() - 1));
}

void SceneReader::index(int32_t i) {
    const Primitive& p = scene_.prims[size_t(i)];
    if (!isModifier(p.type)) {
        surfaces_[p.name] = i;
        return;
    }
    auto [it, added] = modifiers_.try_emplace(p.name, i);
    if (added) return;
    // RADIANCE's insertobject(): an equal redefinition leaves the name where it was.
    if (options_.radianceNumbering && radianceEqualObjects(scene_.prims, modifiers_, i, it->second))
        return;
    it->second = i;
}

void SceneReader::parsePrimitive(SceneLexer& lex, const Context& ctx) {
    std::string modName, typeName, word;
    int line = lex.line(), wordLine = 0;
    SourceLoc loc = ctx.loc(line);
    Primitive p;
    std::string what = "a primitive";
    auto next = [&](const char* expected) {
        if (!lex.readWord(word, wordLine))
            throw InputError(loc,
                             "unexpected end of file in " + what + " (expected " + expected + ")");
        return word;
    };
    modName = next("a modifier");
    line = wordLine;
    loc = ctx.loc(line);
    typeName = next("a primitive type");
    if (!primTypeFromName(typeName, p.type))
        throw InputError(loc, "unknown type '" + typeName + "'");
    p.name = next("an identifier");
    p.loc = loc;
    what = describe(p.type, p.name);

    if (p.type == PrimType::Alias) {
        // ray.html: "mod alias new old" takes old's type and arguments. RADIANCE's
        // getobject(): with "inherit" (or old's own modifier) it keeps old's modifier;
        // any other modifier, void included, replaces it.
        std::string ref = next("the name of the aliased modifier");
        auto it = modifiers_.find(ref);
        if (it == modifiers_.end()) {
            if (surfaces_.count(ref))
                throw InputError(loc, what + ": cannot alias '" + ref + "', a surface");
            throw InputError(loc, what + ": undefined reference '" + ref + "'");
        }
        Primitive copy = scene_.prims[it->second];
        const int32_t targetModifier = copy.modifier;
        copy.name = p.name;
        copy.loc = loc;
        copy.aliasOf = it->second;
        copy.aliasNamed = false;
        if (modName != kInherit) {
            copy.modifier = resolveModifier(modName, loc);
            copy.modifierName = modName;
            copy.aliasNamed = copy.modifier != targetModifier;
        }
        add(std::move(copy));
        return;
    }
    if (modName == kInherit)
        throw InputError(loc, what + ": 'inherit' is only a modifier for an alias");
    p.modifierName = modName;
    try {
        p.modifier = resolveModifier(modName, loc);
    } catch (const InputError& e) {
        throw InputError(loc, what + ": " + e.message());
    }

    auto count = [&](const char* kind) {
        std::string expected = std::string("the number of ") + kind + " arguments";
        next(expected.c_str());
        long n;
        if (!parseInteger(word, n) || n < 0)
            throw InputError(ctx.loc(wordLine),
                             what + ": expected " + expected + ", got '" + word + "'");
        return static_cast<size_t>(n);
    };
    auto eofIn = [&](const char* kind, size_t n, size_t got) {
        return std::string(kind) + " argument " + std::to_string(got + 1) + " of " +
               std::to_string(n);
    };
    size_t ns = count("string");
    p.sargs.reserve(std::min<size_t>(ns, 1024));
    for (size_t i = 0; i < ns; ++i) p.sargs.push_back(next(eofIn("string", ns, i).c_str()));
    size_t ni = count("integer");
    for (size_t i = 0; i < ni; ++i) {
        next(eofIn("integer", ni, i).c_str());
        long v;
        if (!parseInteger(word, v))
            throw InputError(ctx.loc(wordLine), what + ": expected an integer, got '" + word + "'");
        p.iargs.push_back(v);
    }
    size_t nr = count("real");
    p.rargs.reserve(std::min<size_t>(nr, 1 << 16));
    for (size_t i = 0; i < nr; ++i) {
        next(eofIn("real", nr, i).c_str());
        double v;
        if (!parseReal(word, v))
            throw InputError(ctx.loc(wordLine),
                             what + ": expected a real number, got '" + word + "'");
        p.rargs.push_back(v);
    }
    add(std::move(p));
}

Scene parseScene(std::string_view text, const std::string& file, const LoadOptions& options) {
    SceneReader reader(options);
    reader.readText(text, file);
    return reader.take();
}

}  // namespace rp
