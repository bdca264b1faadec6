// objview (see objview.h): RADIANCE 5.4's objview.pl, with its lights and RIF.
#include "rad/objview.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>

#include "util/error.h"
#include "util/options.h"

namespace rp::rad {

namespace {

// objview.pl's light sources: a dim blue glow all around and three small bright suns.
constexpr const char* kLights =
    "void glow dim  0  0  4  .1 .1 .15  0\n"
    "dim source background  0  0  4  0 0 1  360\n"
    "void light bright  0  0  3  1000 1000 1000\n"
    "bright source sun1  0  0  4  1 .2 1  5\n"
    "bright source sun2  0  0  4  .3 1 1  5\n"
    "bright source sun3  0  0  4  -1 -.7 1  5\n";

// A folder removed with what it holds when the run ends.
class TempFolder {
public:
    TempFolder() {
        std::string t = (std::filesystem::temp_directory_path() / "objviewXXXXXX").string();
        if (!::mkdtemp(t.data())) throw InputError("cannot make a temporary folder");
        path_ = t;
    }
    ~TempFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

void writeFile(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    if (!(f << text) || !f.flush()) throw InputError(SourceLoc{path, 0}, "cannot write");
}

// A word for a RIF value: quoted when it holds spaces.
std::string rifWord(const std::string& w) {
    return w.find_first_of(" \t") == std::string::npos ? w : "\"" + w + "\"";
}

}  // namespace

ObjviewCommand parseObjviewArgs(const std::vector<std::string>& args) {
    ObjviewCommand c;
    OptionTable t;
    t.defaultsStops = false;
    t.messages.unknown = [](const std::string& a) { return "bad option: " + a; };
    t.add(valueOption("-u", c.up));
    t.add(valueOption("-v", c.view));
    t.add(valueOption("-o", c.device));
    t.add(valueOption("-r", c.picture));
    for (const char* n : {"-n", "-N"})
        t.add(customOption(n, [&c](OptionReader& r) {
            c.radOptions.push_back("-N");
            c.radOptions.push_back(r.word());
        }));
    for (const char* f : {"-s", "-V", "-e"})
        t.add(customOption(f, [&c](OptionReader& r) { c.radOptions.push_back(r.option()); }));
    t.add(customOption(prefix("-w"), "-w",
                       [&c](OptionReader& r) { c.radOptions.push_back(r.option()); }));
    t.add(customOption("-ap", [&c](OptionReader& r) {
        c.renderOptions += " -ap " + r.word();
        if (r.hasNext() && r.args()[r.next()].find_first_not_of("0123456789") == std::string::npos)
            c.renderOptions += " " + r.word();  // the bandwidth
    }));
    t.add(customOption(prefix("-b"), "-b", [&c](OptionReader&) { c.renderOptions += " -bv"; }));
    for (const char* g : {"-g", "-S"})
        t.add(customOption(g, [](OptionReader& r) {
            throw InputError("glrad output (" + r.option() +
                             ") is not available: objview shows the scene in rvu");
        }));
    std::vector<std::string> words = args;
    const std::size_t first = t.parse(words, 0).next;
    c.inputs.assign(words.begin() + long(first), words.end());
    return c;
}

void runObjview(const ObjviewCommand& cmd, std::istream& in, std::ostream& out,
                const Shell& shell) {
    const TempFolder td;
    std::vector<std::string> scenes = cmd.inputs;
    if (scenes.empty()) {  // a scene on standard input
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        writeFile(td.file("stdin.rad"), text);
        scenes.push_back(td.file("stdin.rad"));
    }
    for (const std::string& s : scenes)
        if (s[0] != '!' && ::access(s.c_str(), R_OK) != 0)
            throw InputError(SourceLoc{s, 0}, "cannot open scene file");
    writeFile(td.file("lights.rad"), kLights);
    scenes.push_back(td.file("lights.rad"));
    std::string sceneWords;
    for (const std::string& s : scenes) sceneWords += (sceneWords.empty() ? "" : " ") + rifWord(s);
    const std::string rif = td.file("ov.rif");
    writeFile(rif, "scene= " + sceneWords + "\nEXPOSURE= .5\nUP= " + cmd.up +
                       "\nview= " + cmd.view + "\nOCTREE= " + td.file("ov.oct") +
                       "\noconv= -f\nAMBF= " + td.file("af.amb") + "\nrender=" + cmd.renderOptions +
                       "\nPICTURE= " + td.file("ov") + "\n");
    std::vector<std::string> args = cmd.radOptions;
    if (cmd.picture.empty()) {
        args.insert(args.begin(), {"-o", cmd.device});
    }
    args.push_back(rif);
    runRad(parseRadArgs(args), out, shell);
    if (cmd.picture.empty()) return;
    const std::string made = td.file("ov_" + cmd.view.substr(0, cmd.view.find(' ')) + ".hdr");
    std::error_code ec;
    std::filesystem::copy_file(made, cmd.picture, std::filesystem::copy_options::overwrite_existing,
                               ec);
    if (ec) throw InputError(SourceLoc{cmd.picture, 0}, "cannot write picture: " + ec.message());
}

}  // namespace rp::rad
