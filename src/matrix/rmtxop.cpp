// rmtxop's argument parsing and evaluation (see rmtxop.h), after RADIANCE rmtxop.c.
#include "matrix/rmtxop.h"

#include <cstdio>
#include <cstdlib>
#include <optional>

#include "matrix/matrix_io.h"
#include "util/error.h"

namespace rp::matrix {

namespace {

constexpr const char* kUsage =
    "Usage: rmtxop [-v][-f[adfc][-t][-s sf .. | -c ce ..][-rf|-rb] m1 [.+*/] .. > mres";

// RADIANCE compat (rtio isflt): a word that is a whole real number.
bool isReal(const std::string& w) {
    if (w.empty()) return false;
    char* end = nullptr;
    std::strtod(w.c_str(), &end);
    return end != w.c_str() && *end == '\0';
}

// Reads up to `most` numbers after args[i]; returns how many.
size_t readFactors(const std::vector<std::string>& args, size_t i, size_t most,
                   std::vector<double>& out) {
    out.clear();
    for (size_t a = i + 1; a < args.size() && out.size() < most && isReal(args[a]); ++a)
        out.push_back(std::atof(args[a].c_str()));
    return out.size();
}

}  // namespace

RmtxopCommand parseRmtxopArgs(const std::vector<std::string>& args) {
    RmtxopCommand cmd;
    UnaryOps pending;  // options for the next matrix
    bsdf::MatrixPart pendingPart = bsdf::MatrixPart::Transmission;
    bool stdinUsed = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.size() == 1 && std::string(".+*/").find(a[0]) != std::string::npos) {
            if (cmd.operands.empty() || cmd.operands.back().nextOp)
                throw InputError(std::string("missing matrix argument before '") + a +
                                 "' operation");
            cmd.operands.back().nextOp = a[0];
        } else if (a.empty() || a[0] != '-' || a.size() == 1) {
            if (a == "-") {
                if (stdinUsed) throw InputError("standard input used for more than one matrix");
                stdinUsed = true;
            }
            if (!cmd.operands.empty() && !cmd.operands.back().nextOp)
                cmd.operands.back().nextOp = '.';
            cmd.operands.push_back({a, pending, 0, pendingPart});
            pending = {};
            pendingPart = bsdf::MatrixPart::Transmission;
        } else {
            switch (a[1]) {
                case 'v':
                    cmd.verbose = true;
                    break;
                case 'f':
                    switch (a.size() > 2 ? a[2] : '\0') {
                        case 'd':
                            cmd.outputType = DataType::Double;
                            break;
                        case 'f':
                            cmd.outputType = DataType::Float;
                            break;
                        case 'a':
                            cmd.outputType = DataType::Ascii;
                            break;
                        case 'c':
                            cmd.outputType = DataType::Rgbe;
                            break;
                        default:
                            throw InputError(std::string("bad option '") + a + "'; " + kUsage);
                    }
                    break;
                case 't':
                    pending.transpose = true;
                    break;
                case 's':
                    i += readFactors(args, i, kMaxComponents, pending.scalars);
                    break;
                case 'c':
                    i +=
                        readFactors(args, i, kMaxComponents * kMaxComponents, pending.coefficients);
                    break;
                case 'r':
                    // RADIANCE compat: the next operand, if an XML BSDF, is read as its
                    // front or back reflection.
                    if (a == "-rf")
                        pendingPart = bsdf::MatrixPart::ReflectionFront;
                    else if (a == "-rb")
                        pendingPart = bsdf::MatrixPart::ReflectionBack;
                    else
                        throw InputError(std::string("bad option '") + a + "'; " + kUsage);
                    break;
                default:
                    throw InputError("unknown operation '" + a + "'; " + kUsage);
            }
        }
    }
    if (cmd.operands.empty()) throw InputError(std::string("no matrix given; ") + kUsage);
    if (cmd.operands.back().nextOp)
        throw InputError(std::string("missing matrix argument after '") +
                         cmd.operands.back().nextOp + "' operation");
    cmd.trailing = pending;
    return cmd;
}

}  // namespace rp::matrix
