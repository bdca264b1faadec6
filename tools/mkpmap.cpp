// mkpmap: generate RADIANCE photon maps (see src/pmap/mkpmap.h). Under mpirun (the build
// in tools/mpi/) every rank traces its share and the first writes the maps.
#include "pmap/mkpmap.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

#include "calc/search_path.h"
#include "cluster_main.h"
#include "gen/builtin_commands.h"
#include "main_errors.h"
#include "pmap/mkpmap_options.h"
#include "render/port_exterior.h"
#include "util/error.h"
#include "util/header.h"
#include "util/paths.h"
#include "util/version.h"
#include "util/warnings.h"

int main(int argc, char** argv) {
    std::ostream* diag = &std::cerr;
    std::ofstream diagFile;
    std::unique_ptr<rp::Cluster> cluster;
    try {
        cluster = rp::tools::startCluster(argc, argv);
        rp::pmap::MkpmapOptions opt = rp::pmap::parseMkpmapArgs(argc, argv);
        if (opt.printVersion || opt.printDefaults) {
            if (cluster->isRoot())
                std::cout << (opt.printVersion ? rp::versionLine() + "\n"
                                               : rp::pmap::formatMkpmapDefaults(opt));
            return rp::tools::endRun(*cluster, 0);
        }
        if (!opt.diagnosticsFile.empty() && cluster->isRoot()) {
            // RADIANCE mkpmap -e: diagnostics appended to the file.
            diagFile.open(opt.diagnosticsFile, std::ios::app);
            if (!diagFile) {
                std::cerr << "mkpmap: cannot open diagnostics file " << opt.diagnosticsFile << '\n';
                return rp::tools::endRun(*cluster, 2);
            }
            diag = &diagFile;
            *diag << "*** " << rp::commandLine(argc, argv) << '\n';
        }
        rp::setWarningSink(
            [diag](const std::string& m) { *diag << "mkpmap: warning: " << m << '\n'; });
        rp::tools::quietUnlessRoot(*cluster);
        const rp::pmap::MkpmapReport report = rp::pmap::runMkpmap(
            opt, rp::commandLine(argc, argv), *diag, rp::gen::builtinLoadOptions(), cluster.get(),
            [](const rp::Scene& scene, const rp::SceneGeometry& geometry,
               const rp::spectral::Pass& pass) {
                return rp::render::portExterior(
                    scene, geometry, rp::calc::defaultSearchPath(rp::projectLibDir()), pass);
            });
        if (std::getenv("RADPHOTON_STATS") && cluster->isRoot())  // for bench/mpi_scaling.sh
            std::cerr << "mkpmap: " << report.storingSeconds << " s storing on the root\n";
        return 0;
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        return rp::tools::failRun(cluster.get(), "mkpmap", e.line, *diag, e.exitCode);
    }
}
