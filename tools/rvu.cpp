// rvu: look at a scene interactively (RADIANCE rvu.1), in a web browser. Options in
// src/rvu/rvu_options.h, commands in src/rvu/session.h, the page in src/rvu/web_display.h.
//   rvu [rpict options] [-n nproc] [-o web[:port]] [-b] [-pe exposure] scene.oct|scene.rad ...
// Prints the page's address (127.0.0.1 only, with a one-time token) and serves it until
// the quit command, SIGINT or SIGTERM.
#include <csignal>
#include <cstdlib>
#include <iostream>

#include "calc/search_path.h"
#include "gen/builtin_commands.h"
#include "geometry/scene_geometry.h"
#include "main_errors.h"
#include "render/rpict.h"
#include "rvu/rvu_options.h"
#include "rvu/session.h"
#include "rvu/web_display.h"
#include "scene/scene_load.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/header.h"
#include "util/paths.h"
#include "util/version.h"
#include "util/warnings.h"

namespace {

std::atomic<bool> stopRequested{false};

void onSignal(int) { stopRequested = true; }

int run(int argc, char** argv) {
    std::vector<std::string> args = rp::argVector(argc, argv);
    args.erase(args.begin());
    rp::rvu::RvuCommand cmd = rp::rvu::parseRvuCommand(args);
    if (cmd.printVersion) {
        std::cout << rp::versionLine() << '\n';
        return 0;
    }
    if (cmd.printDefaults) {
        std::cout << rp::rvu::formatRvuDefaults(cmd.options);
        return 0;
    }
    if (cmd.printDevices) {
        std::cout << rp::rvu::formatRvuDevices();
        return 0;
    }
    const bool warnings = cmd.options.picture.render.warnings;
    rp::setWarningSink([warnings](const std::string& m) {
        if (warnings) std::cerr << "rvu: warning: " << m << std::endl;
    });
    if (cmd.sceneFiles.empty()) throw rp::InputError("missing scene file");
    rp::ViewRays checkView(cmd.options.picture.view);  // before the (slow) scene load

    const auto threads = rp::render::threadLimit(cmd.options.picture.render);
    rp::Scene scene = rp::loadScene(cmd.sceneFiles, rp::gen::builtinLoadOptions());
    rp::SceneGeometry geometry(scene);
    rp::rvu::SessionSetup setup;
    setup.scene = &scene;
    setup.geometry = &geometry;
    setup.searchPath = rp::calc::defaultSearchPath(rp::projectLibDir());
    setup.options = cmd.options;
    setup.commandLine = "rvu";
    for (const auto& f : cmd.sceneFiles)
        setup.sceneName += (setup.sceneName.empty() ? "" : " ") + f;
    rp::rvu::Session session(setup);

    rp::rvu::WebDisplayOptions display;
    display.port = cmd.options.port;
    if (const char* g = std::getenv("DISPLAY_GAMMA"); g && std::atof(g) > 0)
        display.gamma = std::atof(g);  // RADIANCE's variable for the monitor's gamma
    display.stop = &stopRequested;
    display.announce = [](const std::string& url) {
        std::cerr << "rvu: open " << url << " in a web browser" << std::endl;
    };
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::signal(SIGPIPE, SIG_IGN);  // a closed browser connection is not an error
    rp::rvu::runWebDisplay(session, display);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "rvu: " << e.line << std::endl;
        return e.exitCode;
    }
}
