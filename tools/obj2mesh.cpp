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

}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "-n  9\t\t\t\t# triangles per octree leaf\n"
    "-r  16384\t\t\t# octree resolution limit\n"
    "-a  file\t\t\t# material file\n"
    "-l  file\t\t\t# library material file (RAYPATH)\n"
    "-w-\t\t\t\t# warnings on\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::vector<const char*> args(argv, argv + argc);
    args[0] = "obj2mesh";  // a fixed name keeps the header independent of the install path
    bool quiet = false, verbose = false;
    rp::setWarningSink([&quiet](const std::string& m) {
        if (!quiet) std::fprintf(stderr, "obj2mesh: warning: %s\n", m.c_str());
    });
    try {
        rp::MeshWriteOptions opt;
        rp::SceneReader materials;
        int i = 1;
        for (; i < argc && argv[i][0] == '-' && argv[i][1] != '\0'; ++i) {
            std::string o = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) fail("option " + o + " needs a value");
                return argv[++i];
            };
            auto integer = [&]() {
                std::string v = value();
                char* end = nullptr;
                long n = std::strtol(v.c_str(), &end, 10);
                if (v.empty() || *end || n < 1 || n > (1L << 30))
                    fail("option " + o + " needs a positive integer, got '" + v + "'");
                return static_cast<int>(n);
            };
            if (o == "-n") {
                opt.objlim = integer();
            } else if (o == "-r") {
                opt.maxres = integer();
            } else if (o == "-a") {
                materials.readFile(value());
            } else if (o == "-l") {
                std::string name = value();
                auto dirs = rp::calc::defaultSearchPath(rp::projectLibDir());
                auto path = rp::calc::findFile(name, dirs);
                if (!path) fail("cannot find library material: '" + name + "'");
                materials.readFile(*path);
            } else if (o == "-w") {
                quiet = true;
            } else if (o == "-v") {
                verbose = true;
            } else {
                fail("unknown option: '" + o + "'");
            }
        }
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
