// rmtxop(1): loads matrices, applies each one's unary operations (-s scaling or -c
// component transform, then -t transpose), and combines them left to right with '.'
// (product, the default), '+', '*' and '/' (element by element); options after the last
// matrix apply to the result. As RADIANCE rmtxop.c, a chain of products is evaluated from
// the right when that needs fewer operations. The tool's main (tools/rmtxop.cpp) writes
// the result with matrix_io.h.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "bsdf/bsdf.h"
#include "matrix/matrix.h"

namespace rp::matrix {

// RADIANCE rmtxop.c MAXCOMP: at most this many -s factors, its square of -c coefficients.
constexpr int kMaxComponents = 16;

struct UnaryOps {
    std::vector<double> scalars;       // -s
    std::vector<double> coefficients;  // -c
    bool transpose = false;            // -t
};

struct Operand {
    std::string spec;  // file, "-" or "!command"
    UnaryOps ops;
    char nextOp = 0;  // the operation with the next operand ('.', '+', '*', '/'), 0 last
    // What of an XML BSDF operand is read: transmission, or -rf / -rb reflection.
    bsdf::MatrixPart part = bsdf::MatrixPart::Transmission;
};

struct RmtxopCommand {
    std::vector<Operand> operands;
    UnaryOps trailing;                           // options after the last matrix
    DataType outputType = DataType::FromHeader;  // -fa -ff -fd -fc
    bool verbose = false;                        // -v
};

// Parses rmtxop's arguments (without argv[0]). Throws InputError with RADIANCE's usage
// line for a bad option, and for a missing matrix before or after an operator, or "-" used
// twice.
RmtxopCommand parseRmtxopArgs(const std::vector<std::string>& args);

// Loads and combines; -v reports go to `log`, and so do warnings about zero divisions.
// Throws InputError naming the operand for mismatched sizes and bad factor counts.
Matrix runRmtxop(RmtxopCommand& cmd, std::ostream& log);

}  // namespace rp::matrix
