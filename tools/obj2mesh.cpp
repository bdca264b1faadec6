// obj2mesh: compiles a Wavefront .OBJ file into a RADIANCE mesh (.rtm), as RADIANCE's
// obj2mesh does (see src/scene/obj_file.h and src/scene/mesh_write.h).
//   obj2mesh [-a matfile] [-l matlib] [-n objlim] [-r maxres] [-w] [-v] [input.obj [output.rtm]]
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "calc/search_path.h"
#include "info_options.h"
#include "main_errors.h"
#include "scene/mesh_write.h"
#include "scene/obj_file.h"
#include "scene/reader.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"
#include "util/paths.h"
#include "util/warnings.h"

namespace {

[[noreturn]] void fail(const std::string& why) {
    std::fprintf(stderr, "obj2mesh: %s\n", why.c_str());
    std::exit(1);
}

std::string readAll(std::istream& in) {
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// obj2mesh's options (util/options.h), with its messages.
rp::OptionTable obj2meshTable(rp::MeshWriteOptions& opt, rp::SceneReader& materials, bool& quiet,
                              bool& verbose) {
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.messages.missing = [](const std::string& o) { return "option " + o + " needs a value"; };
    t.messages.bad = [](const std::string& o, const std::string& v, rp::ValueKind) {
        return "option " + o + " needs a positive integer, got '" + v + "'";
    };
    t.messages.unknown = [](const std::string& o) { return "unknown option: '" + o + "'"; };
    auto positive = [](const char* name, int& v) {
        return rp::customOption(name,
                                [&v](rp::OptionReader& r) { v = int(r.integer(1, 1L << 30)); });
    };
    t.add(positive("-n", opt.objlim), [&opt] {
        return rp::formatLine("-n  %d\t\t\t\t# triangles per octree leaf\n", opt.objlim);
    });
    t.add(positive("-r", opt.maxres),
          [&opt] { return rp::formatLine("-r  %d\t\t\t# octree resolution limit\n", opt.maxres); });
    t.add(
        rp::customOption("-a", [&materials](rp::OptionReader& r) { materials.readFile(r.word()); }),
        [] { return std::string("-a  file\t\t\t# material file\n"); });
    t.add(rp::customOption("-l",
                           [&materials](rp::OptionReader& r) {
                               const std::string& name = r.word();
                               auto dirs = rp::calc::defaultSearchPath(rp::projectLibDir());
                               auto path = rp::calc::findFile(name, dirs);
                               if (!path)
                                   throw rp::InputError("cannot find library material: '" + name +
                                                        "'");
                               materials.readFile(*path);
                           }),
          [] { return std::string("-l  file\t\t\t# library material file (RAYPATH)\n"); });
    t.add(rp::customOption("-w", [&quiet](rp::OptionReader&) { quiet = true; }),
          [&quiet] { return rp::formatLine("-w%c\t\t\t\t# warnings on\n", quiet ? '+' : '-'); });
    t.add(rp::customOption("-v", [&verbose](rp::OptionReader&) { verbose = true; }));
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    bool quiet = false, verbose = false;
    {
        rp::MeshWriteOptions opt;
        rp::SceneReader materials;
        if (rp::tools::printedInfo(argc, argv,
                                   obj2meshTable(opt, materials, quiet, verbose).formatDefaults()))
            return 0;
    }
    std::vector<const char*> args(argv, argv + argc);
    args[0] = "obj2mesh";  // a fixed name keeps the header independent of the install path
    rp::setWarningSink([&quiet](const std::string& m) {
        if (!quiet) std::fprintf(stderr, "obj2mesh: warning: %s\n", m.c_str());
    });
    try {
        rp::MeshWriteOptions opt;
        rp::SceneReader materials;
        std::vector<std::string> words(argv, argv + argc);
        const int i = int(obj2meshTable(opt, materials, quiet, verbose).parse(words, 1).next);
        if (i < argc - 2) fail("too many file arguments");
        // RADIANCE's header names the options and the input, not the output file.
        int shown = i < argc ? i + 1 : argc;
        std::vector<std::string> header{rp::commandLine(shown, args.data())};

        std::string input = i < argc ? argv[i] : "<stdin>";
        std::string text;
        if (i < argc) {
            FILE* f = std::fopen(argv[i], "rb");
            if (!f) throw rp::InputError(rp::SourceLoc{input, 0}, "cannot open");
            std::string buf(1 << 16, '\0');
            size_t n;
            while ((n = std::fread(buf.data(), 1, buf.size(), f)) > 0) text.append(buf.data(), n);
            std::fclose(f);
        } else {
            text = readAll(std::cin);
        }
        rp::ObjMesh obj = rp::parseObj(text, input);
        rp::Scene mats = materials.take();
        rp::assignObjMaterials(obj, mats);
        rp::MeshSource src;
        src.triangles = std::move(obj.triangles);
        src.materials = std::move(mats);
        rp::MeshStats stats;
        std::string bytes = rp::encodeMeshFile(src, opt, header, &stats);
        if (i == argc - 2) {
            rp::saveMeshFile(argv[i + 1], bytes);
        } else {
            std::fwrite(bytes.data(), 1, bytes.size(), stdout);
            if (std::fflush(stdout) != 0) fail("write error on standard output");
        }
        if (verbose) std::fputs(rp::formatMeshStats(stats).c_str(), stderr);
    } catch (...) {
        fail(rp::tools::currentMainError().line.c_str());
    }
    return 0;
}
