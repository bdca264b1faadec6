// dctimestep(1): daylight-coefficient time steps by matrix products, as RADIANCE 5.4's
// dctimestep.c. Two forms: DCspec [sky] (a matrix times the sky vector or matrix, or a
// set of component pictures "name%03d.hdr" summed with the sky's weights) and
// Vspec Tmat Dmat [sky] (the 3-phase product V T D s). A multi-column sky (gendaymtx)
// gives one result column, or one picture, per time step; -o spec with %d writes each
// step to its own file.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "matrix/matrix_format.h"

namespace rp::matrix {

struct DctimestepOptions {
    int steps = 0;                            // -n: columns of a header-less sky
    bool header = true;                       // -h toggles
    std::string outputSpec;                   // -o file or file%d
    DataType skyType = DataType::FromHeader;  // -if -id -ia (-n alone: ascii)
    DataType outputType = DataType::Ascii;    // -of -od -oa -oc
    std::vector<std::string> inputs;          // DCspec [sky] or Vspec Tmat Dmat [sky]
    std::string commandLine;                  // for output headers
};

// Parses argv (argv[0] the program); throws InputError with RADIANCE's usage lines.
DctimestepOptions parseDctimestepArgs(int argc, const char* const* argv);

// Runs it, writing to `out` unless -o names files. Throws InputError naming the input
// for bad headers, sizes that do not match, short data and pictures that do not agree.
void runDctimestep(const DctimestepOptions& o, std::ostream& out);

// True when `s` holds an integer conversion (%d %i %o %x %X, with a width), not "%%".
bool hasNumberFormat(const std::string& s);
// `spec` with each integer conversion replaced by `n` and "%%" by "%"; InputError for
// any other conversion.
std::string formatNumber(const std::string& spec, int n);

}  // namespace rp::matrix
