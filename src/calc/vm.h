// The .cal virtual machine: compiled code is a flat array of three-address instructions
// over double registers, run by one non-recursive dispatch loop. Calls to variables and
// functions save the caller's live registers and push a small frame record instead of
// recursing in C++, so runaway recursion is caught by counting frames.
//
// Operands are ints indexing one array around register 0: >= 0 is a register, < 0 a
// global. Globals hold, going down: the per-ray variable cache (slot s at -1 - s), a copy
// of the ray's 30 predefined variables and of modifier arguments A1..A16 (refreshed by
// setRay), and the program's constants. Internal to the calc module; users see
// program.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "calc/ir.h"
#include "calc/ray_context.h"

namespace rp::calc {

// Where `$N` and in(n) read their values (rcalc's input columns); set on an Evaluator.
class ChannelSource {
public:
    virtual ~ChannelSource() = default;
    // Value of channel n (n may be < 1: the source reports it as illegal).
    virtual double channel(int n) = 0;
    // in(0): the number of channels in the current record.
    virtual double channelCount() = 0;
};

enum class Code : std::uint8_t {
    Mov,  // d = a
    Neg,  // d = -a
    Add,
    Sub,
    Mul,
    MulAdd,      // d = a*b + c (two roundings, as written)
    Div,         // d = a / b, 0 and counted when b == 0
    Pow,         // d = a ^ b
    PowI,        // d = a ^ b, b an integer immediate
    Math1,       // d = f(a), p = Builtin
    BuiltinN,    // d = f(args at register a, c of them), p = Builtin
    Jmp,         // goto c
    JNP,         // if !(a > 0) goto c
    JNPSub,      // if !(a - b > 0) goto c
    Sel,         // select: index a, b cases; k = 0 gives b and goes to c; else runs the
                 // k-th of the b Jmp instructions that follow. p = NodeInfo
    JCached,     // if variable b is cached for this ray goto c (its code follows inline)
    StVar,       // cache a as variable b
    NeedVar,     // if variable b is not cached for this ray, run its block with a window
                 // starting at register a. p = VarInfo
    LdArg,       // d = modifier argument b (b < 1: their number). p = NodeInfo
    LdArgDyn,    // d = modifier argument round(a)
    LdParam,     // d = function argument b (b < 1: their number). p = NodeInfo
    LdParamDyn,  // d = function argument round(a)
    Call,        // d = function b (arguments in c registers from a). p = NodeInfo
    CallId,      // d = function whose id is argument b (arguments as Call). p = NodeInfo
    Ret,         // return a
    RetVar,      // cache a as variable b, return it
    Chan,        // d = input channel round(a) (b = 1: in(), whose channel 0 is the count)
    Error,       // throw p = NodeInfo (text is the message)
};

struct Instr {
    Code op;
    std::int32_t d = 0, a = 0, b = 0, c = 0;
    const void* p = nullptr;
};

// Each block is generated twice: `start[0]` reads modifier arguments with checked
// loads, `start[1]` reads them from globals and runs when the ray has at least
// `maxArg` arguments.
struct Block {
    int start[2] = {0, 0};  // first instruction
    int frameSize = 0;      // registers used
    int maxArg = 0;         // highest argument that start[1] reads from globals

    int entry(std::size_t nargs) const {
        return start[nargs >= static_cast<std::size_t>(maxArg) ? 1 : 0];
    }
};

// Number of predefined ray variables (Dx .. Kz, NxP .. CbP, DxA .. DzA), stored
// contiguously in RayContext.
constexpr int kRayDoubles = 37;
// Modifier arguments A1 .. A16 are also kept in globals.
constexpr int kArgGlobals = 16;

// All compiled code of a Program. Immutable once built.
struct CodeImage {
    std::vector<Instr> code;
    std::vector<Block> blocks;
    std::vector<int> varBlock;   // per variable slot
    std::vector<int> funcBlock;  // per function; -1 until generated
    std::vector<const FunctionInfo*> functions;
    std::vector<double> constants;
    int nvars = 0;
    int maxArg = 0;  // highest argument read from globals by any block

    int globalCount() const {
        return nvars + kRayDoubles + kArgGlobals + static_cast<int>(constants.size());
    }
    static int varOperand(int slot) { return -1 - slot; }
    int rayOperand(std::size_t byteOffset) const {
        return -nvars - kRayDoubles + static_cast<int>(byteOffset / sizeof(double));
    }
    int argOperand(int n) const {  // n = 1 .. kArgGlobals, ascending in memory
        return -nvars - kRayDoubles - kArgGlobals - 1 + n;
    }
    int constOperand(int index) const { return -nvars - kRayDoubles - kArgGlobals - 1 - index; }
};

// Calls nested deeper than this are reported as runaway recursion.
constexpr int kMaxCallDepth = 20000;

// Mutable per-thread machine state (owned by an Evaluator, or by the linker while
// folding constants).
class Machine {
public:
    // (Re)sizes the globals for `image` and loads its constants.
    void attach(const CodeImage& image);
    // Copies the ray's variables into the globals and forgets cached variables.
    void setRay(const RayContext& ray);

    // Runs a block: `args` become the function arguments (none for variables and
    // expressions).
    double run(int block, const double* args = nullptr, int nargs = 0);
    // Calls any function by id (see builtinFunctionId).
    double call(double id, const double* args, int nargs);

    // Gives variable `slot` a value for the current ray (an external variable).
    void setCached(int slot, double v) {
        r_[CodeImage::varOperand(slot)] = v;
        stamps_[slot] = clock_;
    }
    void setChannels(ChannelSource* channels) { channels_ = channels; }

    // Cached value of a variable for the current ray, if any.
    bool cached(int slot, double& v) const {
        if (stamps_[slot] != clock_) return false;
        v = r_[CodeImage::varOperand(slot)];
        return true;
    }

    long mathErrors = 0;

private:
    struct Frame {
        const Instr* pc;
        std::size_t saved;  // caller's registers saved at saved_[saved ..)
        std::size_t live;   // and how many
        const double* prm;
        int nprm;
        int dst;  // caller register for the result, -1 for none
    };

    const CodeImage* image_ = nullptr;
    const RayContext* ray_ = nullptr;
    RayContext defaultRay_;
    ChannelSource* channels_ = nullptr;
    std::vector<double> mem_;  // globals, then the registers
    double* r_ = nullptr;      // register 0; globals at negative indices
    // Callers' registers and function arguments: kSavedCapacity doubles, allocated once and
    // left unfilled (a zero fill touched 512 KB of fresh pages per machine, several per
    // rendering thread, for a scene whose functions need a few bytes of it).
    static constexpr std::size_t kSavedCapacity = std::size_t{1} << 16;
    std::unique_ptr<double[]> saved_;
    std::vector<std::uint64_t> stamps_;
    std::uint64_t clock_ = 1;
    std::vector<Frame> frames_;
};

// Arithmetic shared with constant folding. RADIANCE compat (calexpr.c, calfunc.c):
// division by zero, a bad power and a library call with a non-finite result give 0,
// counted in mathErrors, instead of stopping the run.
double powerInt(double x, int n, long& mathErrors);

}  // namespace rp::calc
