// xform's scene streams (see xform_scene.h). Behaviour follows RADIANCE's xform(1) manual
// page and src/gen/xform.c: comments copied through, commands expanded (or re-wrapped
// with "| xform -e ..." under -c), surfaces renamed and re-modified, everything else
// keeping its name and modifier. Arguments: xform_args.cpp; records: xform_primitive.cpp.
//
// The scanner here is not scene/lexer.h's: xform copies comments through verbatim and
// keeps a command's backslash continuations, and it must not resolve modifiers (xform
// transforms fragments whose materials are defined elsewhere), so SceneReader cannot be
// used either. Numbers are still checked with the lexer's parseInteger/parseReal.
#include "gen/xform_scene.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>

#include "calc/search_path.h"
#include "gen/xform_format.h"
#include "scene/lexer.h"
#include "util/warnings.h"

namespace rp {

namespace {
constexpr const char* kProgram = "xform";

bool isWhite(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// RADIANCE's getc()-level reading as xform.c does it: words (fgetword), comment lines,
// command lines (fgetline, continuations kept), with line numbers for errors.
class Scanner {
public:
    explicit Scanner(std::string_view text) : text_(text) {}

    bool skipSpace() {
        while (pos_ < text_.size() && isWhite(text_[pos_])) {
            if (text_[pos_] == '\n') ++line_;
            ++pos_;
        }
        return pos_ < text_.size();
    }
    char peek() const { return text_[pos_]; }
    int line() const { return line_; }

    // From the current character through the newline (included, if there is one).
    std::string_view restOfLine() {
        size_t start = pos_;
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        if (pos_ < text_.size()) ++pos_, ++line_;
        return text_.substr(start, pos_ - start);
    }
    // A command line without its final newline; backslash-newlines stay in it.
    std::string commandLine() {
        size_t start = pos_;
        while (pos_ < text_.size() &&
               !(text_[pos_] == '\n' && (pos_ == start || text_[pos_ - 1] != '\\'))) {
            if (text_[pos_] == '\n') ++line_;
            ++pos_;
        }
        return std::string(text_.substr(start, pos_ - start));
    }
    bool word(std::string& w) {
        if (!skipSpace()) return false;
        w.clear();
        char quote = 0;
        if (text_[pos_] == '"' || text_[pos_] == '\'') quote = text_[pos_++];
        while (pos_ < text_.size() && (quote ? text_[pos_] != quote : !isWhite(text_[pos_]))) {
            if (text_[pos_] == '\n') ++line_;
            w += text_[pos_++];
        }
        if (quote) {
            if (pos_ >= text_.size()) return false;  // unterminated quote
            ++pos_;
        }
        return true;
    }

private:
    std::string_view text_;
    size_t pos_ = 0;
    int line_ = 1;
};

std::string shorten(const std::string& s) { return s.size() <= 60 ? s : s.substr(0, 57) + "..."; }

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string runShell(const std::string& command, const SourceLoc& loc) {
    std::fflush(nullptr);
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) throw InputError(loc, "cannot execute !" + shorten(command));
    std::string text;
    char buf[65536];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) text.append(buf, n);
    int status = ::pclose(pipe);
    // RADIANCE's xform ignores the status; as scene/reader.cpp does, we stop instead of
    // writing a silently incomplete scene.
    if (status == -1) throw InputError(loc, "cannot execute !" + shorten(command));
    if (WIFSIGNALED(status))
        throw InputError(loc, "command killed by signal " + std::to_string(WTERMSIG(status)) +
                                  ": !" + shorten(command));
    if (WEXITSTATUS(status) != 0)
        throw InputError(loc, "command failed with exit status " +
                                  std::to_string(WEXITSTATUS(status)) + ": !" + shorten(command));
    return text;
}

// Where a scene file is: as named when it starts with '.', '/' or '~', else the first
// readable one along RAYPATH (default "."), as RADIANCE's getpath() searches; relative
// names and directories are seen from `from` (where xform runs).
std::string findSceneFile(const std::string& name, const std::string& from) {
    if (!name.empty() && (name[0] == '.' || name[0] == '/' || name[0] == '~'))
        return calc::inDirectory(from, name);
    std::string path = ".";
    if (const char* env = std::getenv("RAYPATH"); env && *env) path = env;
    size_t start = 0;
    while (start <= path.size()) {
        size_t end = path.find(':', start);
        if (end == std::string::npos) end = path.size();
        std::string dir = path.substr(start, end - start);
        std::string candidate =
            calc::inDirectory(from, (dir.empty() || dir == ".") ? name : dir + "/" + name);
        if (::access(candidate.c_str(), R_OK) == 0) return candidate;
        start = end + 1;
    }
    throw InputError("cannot find file '" + name + "'");
}

class RunWriter {
public:
    RunWriter(const XformOptions& opts, const XformRun& run, std::string& out)
        : opts_(opts), run_(run), out_(out), xfArgs_(run.transformArgs()) {}

    void header() {
        out_ += '#';
        out_ += " ";
        out_ += kProgram;
        for (size_t a = 1; a < run_.xfEnd; ++a) out_ += " " + run_.argv[a];
        out_ += '\n';
    }

    // One input stream. `file` names it in errors; `context` is where its commands run
    // and the files that led to them (this one included); `fromCommand` fixes every
    // SourceLoc at the command that produced the text.
    void stream(std::string_view text, const std::string& file, const CommandContext& context,
                const SourceLoc* fromCommand, int depth) {
        Scanner sc(text);
        int objects = 0;
        auto loc = [&](int line) { return fromCommand ? *fromCommand : SourceLoc{file, line}; };
        while (sc.skipSpace()) {
            if (sc.peek() == '#') {
                out_ += sc.restOfLine();
            } else if (sc.peek() == '!') {
                SourceLoc at = loc(sc.line());
                command(sc.commandLine(), at, context, depth);
                ++objects;
            } else {
                object(sc, loc);
                ++objects;
            }
        }
        // RADIANCE compat: xform.c warns "warning - empty file" for files and commands.
        if (objects == 0)
            warn(fromCommand ? *fromCommand : SourceLoc{file, 0},
                 fromCommand ? "empty command output" : "empty file");
    }

private:
    void command(const std::string& line, const SourceLoc& loc, const CommandContext& context,
                 int depth) {
        if (!run_.expand) {
            // xform.c xfcomm(): pass the command on, piped through an xform that expands
            // it next time with this run's options (-c left out).
            out_ += "\n" + line;
            if (run_.xfEnd > 1) {
                out_ += std::string(" | ") + kProgram + " -e";
                for (size_t i = 1; i < run_.xfEnd; ++i)
                    if (i >= run_.xfBegin || run_.argv[i] != "-c") out_ += " " + run_.argv[i];
            }
            out_ += '\n';
            return;
        }
        std::string cmd = line.substr(1);  // drop the '!'
        if (depth >= opts_.maxCommandDepth)
            throw InputError(loc, "commands nested too deeply: !" + shorten(cmd));
        std::optional<std::string> output;
        if (opts_.commandHook) {
            std::string joined;  // the hook sees the command as the shell would join it
            for (size_t i = 0; i < cmd.size(); ++i) {
                if (cmd[i] == '\\' && i + 1 < cmd.size() && cmd[i + 1] == '\n')
                    ++i;
                else
                    joined += cmd[i];
            }
            joined.erase(0, joined.find_first_not_of(" \t"));
            output = opts_.commandHook(joined, loc, context);
        }
        // RADIANCE compat: xform runs a file's commands in that file's directory.
        const std::string& dir = context.dir;
        if (!output)
            output = runShell(dir.empty() ? cmd : "cd " + shellQuote(dir) + " && " + cmd, loc);
        try {
            stream(*output, loc.file, context, &loc, depth + 1);
        } catch (const InputError& e) {
            if (e.message().find(" (in output of !") != std::string::npos) throw;
            throw InputError(e.loc(), e.message() + " (in output of !" + shorten(cmd) + ")");
        }
    }

    template <class Loc>
    void object(Scanner& sc, const Loc& loc) {
        Primitive p;
        std::string typeName, w;
        p.loc = loc(sc.line());
        if (!sc.word(p.modifierName)) throw InputError(p.loc, "unexpected end of file");
        p.loc = loc(sc.line());
        if (!sc.word(typeName))
            throw InputError(p.loc, "unexpected end of file (expected an object type)");
        if (!primTypeFromName(typeName, p.type))
            throw InputError(p.loc, "unknown object type '" + typeName + "'");
        if (!sc.word(p.name))
            throw InputError(p.loc, "unexpected end of file (expected an identifier)");
        std::string bad = "bad " + typeName + " '" + p.name + "': ";
        if (p.type == PrimType::Alias) {
            if (!sc.word(w)) throw InputError(p.loc, bad + "missing the aliased name");
            p.sargs.push_back(w);
            out_ += "\n" + formatPrimitive(p);
            return;
        }
        auto count = [&](const char* kind) {
            long n;
            if (!sc.word(w) || !parseInteger(w, n) || n < 0)
                throw InputError(p.loc, bad + "expected the number of " + kind + " arguments");
            return static_cast<size_t>(n);
        };
        auto eof = [&](const char* kind) {
            return InputError(p.loc, bad + "unexpected end of file in " + kind + " arguments");
        };
        for (size_t i = 0, n = count("string"); i < n; ++i) {
            if (!sc.word(w)) throw eof("string");
            p.sargs.push_back(w);
        }
        for (size_t i = 0, n = count("integer"); i < n; ++i) {
            long v;
            if (!sc.word(w)) throw eof("integer");
            if (!parseInteger(w, v)) throw InputError(p.loc, bad + "bad integer '" + w + "'");
            p.iargs.push_back(v);
        }
        for (size_t i = 0, n = count("real"); i < n; ++i) {
            double v;
            if (!sc.word(w)) throw eof("real");
            if (!parseReal(w, v)) throw InputError(p.loc, bad + "bad real '" + w + "'");
            p.rargs.push_back(v);
        }
        if (isSurface(p.type)) {
            // Only surfaces are renamed and re-modified: modifiers keep their names so
            // that the surfaces' references to them still hold.
            if (!run_.newModifier.empty()) p.modifierName = run_.newModifier;
            if (!run_.idPrefix.empty()) p.name = run_.idPrefix + "." + p.name;
        } else if (p.type == PrimType::Mist && !run_.idPrefix.empty()) {
            // xform.c m_mist(): the named light sources are surfaces, so they were renamed;
            // each '>'-separated name in an argument gets the prefix.
            for (std::string& s : p.sargs) {
                std::string renamed;
                size_t start = 0;
                while (start < s.size()) {
                    size_t end = s.find('>', start);
                    end = end == std::string::npos ? s.size() : end + 1;
                    renamed += run_.idPrefix + "." + s.substr(start, end - start);
                    start = end;
                }
                s = renamed;
            }
        }
        transformPrimitive(p, run_.xf, xfArgs_, run_.invert);
        out_ += "\n" + formatPrimitive(p);
    }

    const XformOptions& opts_;
    const XformRun& run_;
    std::string& out_;
    std::vector<std::string> xfArgs_;
};

}  // namespace

// ---------------------------------------------------------------------------------------

std::string includeKey(const std::string& path) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : p.string();
}

std::string xformScene(const XformOptions& opts, std::istream& in) {
    std::string out;
    std::optional<std::string> stdinText;  // read once, reused by every copy
    for (const XformRun& run : opts.runs) {
        RunWriter writer(opts, run, out);
        writer.header();
        std::vector<std::string> files = run.files();
        if (files.empty()) {
            if (!stdinText)
                stdinText.emplace(std::istreambuf_iterator<char>(in),
                                  std::istreambuf_iterator<char>());
            writer.stream(*stdinText, "", opts.context, nullptr, 0);
            continue;
        }
        for (const std::string& name : files) {
            std::string path = findSceneFile(name, opts.context.dir);
            if (path.size() > 2 && path[0] == '.' && path[1] == '/') path.erase(0, 2);
            CommandContext inner;
            inner.includeChain = opts.context.includeChain;
            inner.includeChain.push_back(includeKey(path));
            const auto& chain = opts.context.includeChain;
            if (std::find(chain.begin(), chain.end(), inner.includeChain.back()) != chain.end())
                throw InputError(opts.context.includer,
                                 "scene file includes itself (" + path + ")");
            std::ifstream f(path, std::ios::binary);
            if (!f) throw InputError(SourceLoc{path, 0}, "cannot open file");
            std::string text{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
            size_t slash = path.rfind('/');
            std::string dir = slash == std::string::npos ? ""
                              : slash == 0               ? "/"
                                                         : path.substr(0, slash);
            inner.dir = run.expand ? dir : opts.context.dir;
            writer.stream(text, path, inner, nullptr, 0);
        }
    }
    return out;
}

std::string xformText(const XformOptions& opts, std::string_view text) {
    std::istringstream in{std::string(text)};
    return xformScene(opts, in);
}

}  // namespace rp
