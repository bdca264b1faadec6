#include "gen/builtin_commands.h"

#include <cstdlib>
#include <functional>
#include <sstream>

#include "calc/search_path.h"
#include "gen/genblinds.h"
#include "gen/genbox.h"
#include "gen/gendaylit.h"
#include "gen/genprism.h"
#include "gen/genrev.h"
#include "gen/gensky.h"
#include "gen/gensurf.h"
#include "gen/genworm.h"
#include "gen/mgf2rad.h"
#include "gen/pkgbsdf.h"
#include "gen/xform_scene.h"
#include "util/warnings.h"

namespace rp::gen {

namespace {

// A generator: arguments (args[0] = its name), standard input and where it runs -> scene
// text.
using Generator =
    std::function<std::string(const std::vector<std::string>& args, const std::string& input,
                              const SourceLoc& loc, const CommandContext& context)>;

std::optional<std::string> runInContext(const std::string& command, const SourceLoc& loc,
                                        const CommandContext& context);

// RAYPATH (or ".") as seen from the directory the command runs in.
std::vector<std::string> searchPathFrom(const CommandContext& context) {
    std::vector<std::string> dirs = calc::defaultSearchPath("");
    if (context.dir.empty()) return dirs;
    for (std::string& d : dirs) d = calc::inDirectory(context.dir, d);
    return dirs;
}

void reportWarnings(const std::string& program, const std::vector<std::string>& warnings,
                    const SourceLoc& loc) {
    for (const std::string& w : warnings) warn(loc, program + ": " + w);
}

// genrev, gensurf and genworm find -f files as their tools do: along RAYPATH, else in
// the directory the shell would have run the command in.
template <class Fn>
std::string withSearchPath(const char* program, const SourceLoc& loc, const CommandContext& context,
                           Fn&& run) {
    std::vector<std::string> warnings;
    std::string out = run(searchPathFrom(context), warnings);
    reportWarnings(program, warnings, loc);
    return out;
}

const Generator* findGenerator(const std::string& name) {
    static const std::vector<std::pair<std::string, Generator>> table = {
        {"genbox",
         [](const auto& args, const auto&, const auto&, const auto&) { return genbox(args); }},
        {"genblinds",
         [](const auto& args, const auto&, const auto&, const auto&) { return genblinds(args); }},
        {"genprism",
         [](const auto& args, const auto& input, const auto&, const auto&) {
             std::istringstream in(input);
             return genprism(args, in);
         }},
        {"gensky",
         [](const auto& args, const auto&, const auto& loc, const auto&) {
             std::vector<std::string> warnings;
             std::string out = gensky(args, &warnings);
             reportWarnings("gensky", warnings, loc);
             return out;
         }},
        {"gendaylit",
         [](const auto& args, const auto&, const auto& loc, const auto&) {
             std::vector<std::string> warnings;
             std::string out = gendaylit(args, &warnings);
             reportWarnings("gendaylit", warnings, loc);
             return out;
         }},
        {"genrev",
         [](const auto& args, const auto&, const auto& loc, const auto& context) {
             return withSearchPath("genrev", loc, context, [&](const auto& path, auto& warnings) {
                 return genrev(args, path, warnings);
             });
         }},
        {"gensurf",
         [](const auto& args, const auto& input, const auto& loc, const auto& context) {
             std::istringstream in(input);
             return withSearchPath("gensurf", loc, context, [&](const auto& path, auto& warnings) {
                 return gensurf(args, path, in, warnings);
             });
         }},
        {"genworm",
         [](const auto& args, const auto&, const auto& loc, const auto& context) {
             return withSearchPath("genworm", loc, context, [&](const auto& path, auto& warnings) {
                 return genworm(args, path, warnings);
             });
         }},
        {"mgf2rad",
         [](const auto& args, const auto& input, const auto& loc, const auto& context) {
             std::vector<std::string> warnings;
             std::string out;
             try {
                 out = mgf2rad(args, input, warnings, context.dir);
             } catch (const InputError& e) {
                 throw InputError(e.what());  // keeps the MGF file and line in the message
             }
             reportWarnings("mgf2rad", warnings, loc);
             return out;
         }},
        {"pkgBSDF",
         [](const auto& args, const auto&, const auto& loc, const auto& context) {
             std::vector<std::string> warnings;
             std::string out;
             try {
                 out = pkgBSDF(args, warnings, searchPathFrom(context), context.dir);
             } catch (const InputError& e) {
                 throw InputError(e.what());
             }
             reportWarnings("pkgBSDF", warnings, loc);
             return out;
         }},
        {"xform",
         [](const auto& args, const auto& input, const auto&, const auto& context) {
             // Commands in the files it reads run here too, in their files' folders.
             std::istringstream in(input);
             XformOptions opts = parseXformArgs(args);
             opts.commandHook = runInContext;
             opts.context = context;
             return xformScene(opts, in);
         }},
    };
    for (const auto& [n, g] : table)
        if (n == name) return &g;
    return nullptr;
}

bool shellRequested() {
    const char* v = std::getenv(kShellCommandsEnv);
    return v && *v && std::string_view(v) != "0";
}

}  // namespace

std::optional<std::vector<std::vector<std::string>>> splitPipeline(std::string_view command) {
    std::vector<std::vector<std::string>> stages(1);
    std::string word;
    bool inWord = false;
    auto endWord = [&] {
        if (inWord) stages.back().push_back(word);
        word.clear();
        inWord = false;
    };
    for (size_t i = 0; i < command.size(); ++i) {
        char c = command[i];
        if (c == ' ' || c == '\t' || c == '\n') {
            endWord();
        } else if (c == '|') {
            endWord();
            if (stages.back().empty()) return std::nullopt;  // "||" or a leading '|'
            stages.emplace_back();
        } else if (c == '\'') {
            size_t end = command.find('\'', i + 1);
            if (end == std::string_view::npos) return std::nullopt;
            word.append(command.substr(i + 1, end - i - 1));
            inWord = true;
            i = end;
        } else if (c == '"') {
            inWord = true;
            for (++i; i < command.size() && command[i] != '"'; ++i) {
                char d = command[i];
                if (d == '$' || d == '`') return std::nullopt;
                if (d == '\\' && i + 1 < command.size() &&
                    std::string_view("\"\\$`\n").find(command[i + 1]) != std::string_view::npos)
                    d = command[++i];
                word.push_back(d);
            }
            if (i >= command.size()) return std::nullopt;
        } else if (c == '\\') {
            if (i + 1 >= command.size()) return std::nullopt;
            word.push_back(command[++i]);
            inWord = true;
        } else if (std::string_view(";&<>()$`*?[]{}~#").find(c) != std::string_view::npos) {
            return std::nullopt;  // needs the shell
        } else {
            word.push_back(c);
            inWord = true;
        }
    }
    endWord();
    if (stages.back().empty()) return std::nullopt;
    return stages;
}

namespace {

std::optional<std::string> runInContext(const std::string& command, const SourceLoc& loc,
                                        const CommandContext& context) {
    if (shellRequested()) return std::nullopt;
    auto stages = splitPipeline(command);
    if (!stages) return std::nullopt;
    std::vector<const Generator*> generators;
    for (const auto& stage : *stages) {
        const Generator* g = findGenerator(stage.front());
        if (!g) return std::nullopt;
        generators.push_back(g);
    }
    std::string text;
    for (size_t i = 0; i < stages->size(); ++i) {
        const auto& args = (*stages)[i];
        try {
            CommandContext here = context;
            here.includer = loc;
            text = (*generators[i])(args, text, loc, here);
        } catch (const InputError& e) {
            if (!e.loc().file.empty()) throw;  // names its place already (an included file's)
            throw InputError(loc, args.front() + ": " + e.message());
        }
    }
    return text;
}

}  // namespace

std::optional<std::string> runBuiltinCommand(const std::string& command, const SourceLoc& loc) {
    // A scene file's own commands run in the current directory (oconv, rtrace); the file
    // starts the chain of files that its commands include.
    CommandContext context;
    if (!loc.file.empty()) context.includeChain.push_back(includeKey(loc.file));
    return runInContext(command, loc, context);
}

ContextCommandHook builtinCommandHook() { return runInContext; }

LoadOptions builtinLoadOptions() {
    LoadOptions options;
    options.commandHook = runBuiltinCommand;
    return options;
}

}  // namespace rp::gen
