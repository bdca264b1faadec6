// getinfo: print the information header of RADIANCE files (see src/image/getinfo.h).
#include "image/getinfo.h"

#include <cstdio>
#include <iostream>

#include "gen/builtin_commands.h"
#include "geometry/scene_geometry.h"
#include "info_options.h"
#include "main_errors.h"
#include "scene/scene_load.h"
#include "util/error.h"

namespace {
// -d on our scene files: the cube RADIANCE's oconv would store, printed as its
// writeoct prints one.
std::string sceneCube(const std::string& path) {
    rp::Scene scene = rp::loadScene({path}, rp::gen::builtinLoadOptions());
    rp::SceneCube c = rp::SceneGeometry(scene).sceneCube();
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.12g %.12g %.12g %.12g", c.origin.x, c.origin.y, c.origin.z,
                  c.size);
    return buf;
}
}  // namespace

// -defaults (tools/info_options.h).
constexpr const char* kDefaults =
    "getinfo [-d|+d] [-a line ..] [file ..]	# headers of pictures, octrees, photon maps\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kDefaults)) return 0;
    std::ios::sync_with_stdio(false);
    try {
        rp::GetinfoOptions opt = rp::parseGetinfoArgs(argc, argv);
        opt.sceneCube = sceneCube;
        int status = rp::runGetinfo(opt, std::cin, std::cout, std::cerr);
        std::cout.flush();
        return status;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "getinfo: " << e.line << '\n';
        return e.exitCode;
    }
}
