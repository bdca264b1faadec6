// xform's command line (see xform_scene.h): initial options, the transform, files, and
// RADIANCE's argv rewriting for arrays (-a, doarray() in src/gen/xform.c) and argument
// files (-f, doargf()), so each copy's header line reads as RADIANCE's does.
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

#include "gen/xform_scene.h"
#include "scene/lexer.h"
#include "util/options.h"

namespace rp {

namespace {
constexpr const char* kProgram = "xform";

bool isWhite(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// Values each transform option takes (scene/xform.h spells the options).
size_t transformValues(const std::string& opt) {
    if (opt == "-t") return 3;
    if (opt == "-mx" || opt == "-my" || opt == "-mz") return 0;
    return 1;
}

// xform's initial options (util/options.h): any other word starts the transform, and
// so does a -m or -n without its value (RADIANCE xform.c main), which the transform
// then refuses.
OptionTable initialOptions(XformRun& run) {
    OptionTable t;
    t.defaultsStops = false;
    t.unknownEnds = true;
    t.messages.missing = [](const std::string& opt) {
        return "command line error at '" + opt + "'";
    };
    t.add(customOption("-m", [&run](OptionReader& r) {
        const std::string& v = r.word();
        if (run.newModifier.empty()) run.newModifier = v;  // RADIANCE: first -m wins
    }));
    t.add(customOption("-n", [&run](OptionReader& r) {
        const std::string& v = r.word();
        run.idPrefix = run.idPrefix.empty() ? v : run.idPrefix + "." + v;
    }));
    t.add(customOption("-c", [&run](OptionReader&) { run.expand = false; }));
    t.add(customOption("-e", [&run](OptionReader&) { run.expand = true; }));
    t.add(customOption("-I", [&run](OptionReader&) { run.invert = !run.invert; }));
    return t;
}

// RADIANCE main() without -a/-f: initial options, transform, files.
XformRun parseRun(const std::vector<std::string>& av) {
    XformRun run;
    run.argv = av;
    std::vector<std::string> words = av;
    // -version (answered by the tool's main) stops the options too, as any other word.
    size_t a = initialOptions(run).parse(words, 1).next;
    run.xfBegin = a;
    while (a < av.size() && isTransformOption(av[a]) && a + transformValues(av[a]) < av.size())
        a += 1 + transformValues(av[a]);
    run.xfEnd = a;
    if (a < av.size() && !av[a].empty() && av[a][0] == '-')
        throw InputError("command line error at '" + av[a] + "'");
    run.xf = parseTransform(run.transformArgs(), 0, SourceLoc{});
    return run;
}

// Words of one -f line as RADIANCE's doargf() splits them: white space separates,
// a quote at the start of a word runs to the matching quote.
std::vector<std::string> splitWords(std::string_view line) {
    std::vector<std::string> words;
    size_t i = 0;
    while (true) {
        while (i < line.size() && isWhite(line[i])) ++i;
        if (i >= line.size()) break;
        std::string w;
        if (line[i] == '"' || line[i] == '\'') {
            char q = line[i++];
            while (i < line.size() && line[i] != q) w += line[i++];
            if (i < line.size()) ++i;
        } else {
            while (i < line.size() && !isWhite(line[i])) w += line[i++];
        }
        words.push_back(std::move(w));
    }
    return words;
}

// An -f line: a leading "!" and "xform " are ignored (xform(1)).
std::vector<std::string> splitArgLine(std::string_view line) {
    if (!line.empty() && line[0] == '!') line.remove_prefix(1);
    if (line.substr(0, 6) == "xform ") line.remove_prefix(6);
    return splitWords(line);
}

// Lines of an argument file, backslash-newline continuations joined (fgetline()).
std::vector<std::string> readArgLines(std::istream& in) {
    std::vector<std::string> lines;
    std::string line, part;
    while (std::getline(in, part)) {
        if (!part.empty() && part.back() == '\\') {
            part.pop_back();
            line += part + " ";
            continue;
        }
        lines.push_back(line + part);
        line.clear();
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

struct ArgExpander {
    std::istream* argLines;
    XformOptions& out;
    bool stdinUsed = false;

    void expand(const std::vector<std::string>& av, int depth) {
        if (depth > 32) throw InputError("-f argument files nested too deeply");
        for (size_t a = 1; a < av.size(); ++a)
            if (av[a] == "-f") return argFile(av, a, depth);
        for (size_t a = 1; a < av.size(); ++a)
            if (av[a] == "-a") return array(av, a, depth);
        out.runs.push_back(parseRun(av));
    }

    // RADIANCE doarray(): copy k replaces "-a n" by "-i k" and names itself a<k>, or
    // <name>.<k> under -n name.
    void array(const std::vector<std::string>& av, size_t ai, int depth) {
        long n = 0;
        if (ai + 1 >= av.size() || !parseInteger(av[ai + 1], n) || n <= 0)
            throw InputError("missing count for -a option");
        std::vector<size_t> idAt;
        std::string oldId;
        for (size_t i = 1; i < av.size(); ++i)
            if (av[i - 1] == "-n") idAt.push_back(i), oldId = av[i];
        for (long k = 0; k < n; ++k) {
            std::vector<std::string> copy = av;
            copy[ai] = "-i";
            copy[ai + 1] = std::to_string(k);
            for (size_t i : idAt) copy[i] = oldId + "." + std::to_string(k);
            if (idAt.empty()) copy.insert(copy.begin() + 1, {"-n", "a" + std::to_string(k)});
            expand(copy, depth + 1);
        }
    }

    // RADIANCE doargf(): each line of the file is a separate invocation with its words in
    // place of "-f file", named i<k> or <name>.<k>.
    void argFile(const std::vector<std::string>& av, size_t fi, int depth) {
        if (fi + 1 >= av.size() || (av[fi + 1].size() > 1 && av[fi + 1][0] == '-'))
            throw InputError("missing file for -f option");
        std::vector<std::string> lines;
        const std::string& file = av[fi + 1];
        if (file == "-") {
            if (stdinUsed || !argLines) throw InputError("cannot use stdin more than once");
            stdinUsed = true;
            lines = readArgLines(*argLines);
        } else {
            std::ifstream in(file);
            if (!in) throw InputError("cannot open argument file '" + file + "'");
            lines = readArgLines(in);
        }
        int k = 0;
        for (const std::string& line : lines) {
            if (line.empty() || line[0] == '#') continue;
            std::vector<std::string> copy(av.begin(), av.begin() + static_cast<long>(fi));
            for (std::string& w : splitArgLine(line)) copy.push_back(std::move(w));
            copy.insert(copy.end(), av.begin() + static_cast<long>(fi) + 2, av.end());
            bool named = false;
            for (size_t i = 2; i < copy.size() && !named; ++i)
                if (copy[i - 1] == "-n") copy[i] += "." + std::to_string(k), named = true;
            if (!named) copy.insert(copy.begin() + 1, {"-n", "i" + std::to_string(k)});
            expand(copy, depth + 1);
            ++k;
        }
        if (k == 0) throw InputError("empty argument file '" + file + "'");
    }
};
}  // namespace

XformOptions parseXformArgs(const std::vector<std::string>& args, std::istream* argLines) {
    XformOptions opts;
    std::vector<std::string> av = args;
    if (av.empty()) av.push_back(kProgram);
    av[0] = kProgram;  // headers say "xform", wherever the binary lives
    ArgExpander ex{argLines, opts};
    ex.expand(av, 0);
    if (ex.stdinUsed)
        for (const XformRun& r : opts.runs)
            if (r.xfEnd == r.argv.size()) throw InputError("cannot use stdin more than once");
    return opts;
}

XformOptions parseXformArgs(int argc, const char* const* argv, std::istream* argLines) {
    return parseXformArgs(std::vector<std::string>(argv, argv + argc), argLines);
}

}  // namespace rp
