// rmtxop: RADIANCE's matrix calculator (see src/matrix/rmtxop.h).
//   rmtxop [-v][-f[adfc]][-t][-s sf ..|-c ce ..] m1 [.+*/] [-t][-s ..|-c ..] m2 .. > mres
#include "matrix/rmtxop.h"

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "info_options.h"
#include "main_errors.h"
#include "matrix/matrix_io.h"
#include "util/error.h"
#include "util/header.h"

// -defaults (tools/info_options.h): the synopsis, as for the generators.
constexpr const char* kSynopsis =
    "rmtxop [-v][-f[adfc]][-t][-s sf ..|-c ce ..] m1 [.+*/] .. > mres\n";

int main(int argc, char** argv) {
    if (rp::tools::printedInfo(argc, argv, kSynopsis)) return 0;
    try {
        std::ios::sync_with_stdio(false);
        rp::matrix::RmtxopCommand cmd =
            rp::matrix::parseRmtxopArgs(std::vector<std::string>(argv + 1, argv + argc));
        const rp::matrix::Matrix m = rp::matrix::runRmtxop(cmd, std::cerr);
        // The whole output is built first, so an error leaves standard output empty.
        std::ostringstream out;
        out << rp::kHeaderMagic << '\n' << rp::commandLine(argc, argv) << '\n';
        rp::matrix::writeMatrix(out, m, cmd.outputType);
        std::cout << out.str();
        std::cout.flush();
        if (!std::cout) throw rp::InputError("error writing result matrix");
        return 0;
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        std::cerr << "rmtxop: " << e.line << '\n';
        return e.exitCode;
    }
}
