// rcollate(1): reshapes, transposes or block-reorders the records of a matrix file
// without interpreting them: ASCII records of N words, or binary records of N floats,
// doubles or bytes. Follows RADIANCE rcollate.c, header handling included: the input
// header is copied (less FORMAT/NROWS/NCOLS/NCOMP), then the command's options, NCOMP=,
// FORMAT=, NROWS= and NCOLS=.
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "matrix/matrix_input.h"

namespace rp::matrix {

struct RcollateOptions {
    std::string format;     // -fa -ff -fd -fb: "ascii", "float", "double", "byte"; "" unset
    int componentSize = 0;  // bytes per binary word (0: ASCII)
    int components = 0;     // words per record (-f..N; 0: from the header or 3)
    int inCols = 0, inRows = 0, outCols = 0, outRows = 0;  // -ic -ir -oc -or
    bool transpose = false;                                // -t toggles
    bool inHeader = true, outHeader = true;                // -h, -hi, -ho
    bool warnings = true;                                  // -w toggles
    bool check = false;                                    // -c
    // -o RxC[xR1xC1..]: each level's size in records, the first the whole output
    // (RADIANCE's outArray, products of the inner levels).
    std::vector<std::pair<int, int>> blocks;
    std::string commandLine;  // the program and its options, for the output header
    std::string input;        // the input file; "" for standard input
};

// Parses argv (argv[0] the program). Throws InputError with RADIANCE's usage line.
RcollateOptions parseRcollateArgs(int argc, const char* const* argv);

// Runs rcollate on the input's bytes. Warnings (no-op copy, incomplete final row,
// characters beyond the data) go through util/warnings.h. Throws InputError for bad
// headers, sizes that do not fit and short records.
void runRcollate(RcollateOptions o, const InputData& in, std::ostream& out);

}  // namespace rp::matrix
