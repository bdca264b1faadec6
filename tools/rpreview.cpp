// rpreview: quick eye-light preview of a scene's geometry, written as a RADIANCE
// picture; prints scene statistics and ray throughput to stderr.
//   rpreview [view options] [-x res] [-y res] [-o out.hdr] scene.rad|scene.oct ...
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "gen/builtin_commands.h"
#include "geometry/scene_geometry.h"
#include "info_options.h"
#include "main_errors.h"
#include "render/preview.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"

namespace {

// rpreview's options (util/options.h): the view options, -x -y -o; a value option at the
// end of the line, without its value, is an unknown option as it always was.
rp::OptionTable rpreviewTable(rp::PreviewOptions& opt, std::string& out) {
    rp::OptionTable t;
    t.defaultsStops = false;  // -defaults is info_options.h's, at argv[1]
    t.messages.missing = t.messages.unknown;
    t.messages.bad = [](const std::string& o, const std::string& v, rp::ValueKind) {
        return "bad value for " + o + ": '" + v + "'";
    };
    t.add(rp::viewOptionSpec(opt.view));
    auto resolution = [&t](const char* name, int& v) {
        t.add(rp::customOption(name, [&v](rp::OptionReader& r) { v = int(r.integer(1, 100000)); }),
              [name, &v] {
                  return rp::formatLine("%s  %d\t\t\t\t# %c resolution\n", name, v, name[1]);
              });
    };
    resolution("-x", opt.xres);
    resolution("-y", opt.yres);
    t.add(rp::valueOption("-o", out), [&out] {
        return rp::formatLine("-o  %s\t\t\t\t# output picture (standard output)\n",
                              out.empty() ? "-" : out.c_str());
    });
    t.setDefaultsOrder({"-x", "-y", "-o"});
    return t;
}

int run(int argc, char** argv) {
    rp::PreviewOptions opt;
    std::string out;
    std::vector<std::string> files;
    // Options may stand anywhere among the scene files.
    std::vector<std::string> args(argv, argv + argc);
    const rp::OptionTable table = rpreviewTable(opt, out);
    for (size_t i = table.parse(args, 1).next; i < args.size(); i = table.parse(args, i + 1).next)
        files.push_back(args[i]);
    if (files.empty())
        throw rp::InputError(
            "usage: rpreview [view options] [-x res] [-y res] [-o out.hdr] scene ...");
    rp::Scene scene = rp::loadScene(files, rp::gen::builtinLoadOptions());
    rp::SceneGeometry geometry(scene);
    std::map<std::string, int> counts;
    for (const auto& p : scene.prims) counts[std::string(rp::primTypeName(p.type))]++;
    std::fprintf(stderr, "rpreview: %zu primitives (", scene.prims.size());
    bool first = true;
    for (auto& [t, n] : counts)
        std::fprintf(stderr, "%s%d %s", first ? "" : ", ", n, t.c_str()), first = false;
    std::fprintf(stderr, "), %zu triangles, %zu distant sources\n", geometry.triangleCount(),
                 geometry.sources().size());
    rp::PreviewStats stats;
    rp::Picture pic = rp::renderPreview(scene, geometry, opt, &stats);
    pic.header.lines.insert(pic.header.lines.begin(), rp::commandLine(argc, argv));
    std::fprintf(stderr, "rpreview: %dx%d, %ld rays, %.1f%% hit, %.2f M rays/s\n", pic.width,
                 pic.height, stats.rays, 100.0 * stats.hits / std::max(1L, stats.rays),
                 stats.rays / std::max(1e-9, stats.seconds) * 1e-6);
    if (out.empty())
        rp::writePicture(std::cout, pic);
    else
        rp::writePicture(out, pic);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    {
        rp::PreviewOptions opt;
        std::string out;
        if (rp::tools::printedInfo(argc, argv, rpreviewTable(opt, out).formatDefaults())) return 0;
    }
    try {
        return run(argc, argv);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::fprintf(stderr, "rpreview: %s\n", e.line.c_str());
        return e.exitCode;
    }
}
