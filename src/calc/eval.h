// Compiled form of .cal code and the functions that evaluate it: a tree of Nodes, each
// carrying a pointer to its evaluation function and its operands already resolved
// (variable slots, parameter indices, ray-variable offsets, callee pointers). Nothing
// here parses or looks names up. Internal to the calc module; users see program.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "calc/ray_context.h"
#include "util/error.h"

namespace rp::calc {

struct Node;
struct EvalState;
using EvalFn = double (*)(const Node&, EvalState&);

// Where a node came from and what to say if it fails at run time.
struct NodeInfo {
    SourceLoc loc;
    std::string text;  // name or complete error message
};

struct VarInfo {
    std::string name;
    int slot = 0;
    const Node* body = nullptr;
    SourceLoc loc;
};

struct FunctionInfo {
    std::string name;
    int nparams = 0;
    bool constant = false;       // defined with ':'
    bool pure = false;           // body depends only on its parameters
    std::vector<bool> paramCalled;
    const Node* body = nullptr;
    SourceLoc loc;
};

struct Node {
    EvalFn fn = nullptr;
    const Node* a = nullptr;
    const Node* b = nullptr;
    const Node* c = nullptr;
    const Node* const* kids = nullptr;  // calls and select: all arguments
    int nkids = 0;
    int index = 0;                      // slot, parameter, exponent, byte offset
    double num = 0;                     // constant value
    const void* ptr = nullptr;          // VarInfo, FunctionInfo, Builtin
    const NodeInfo* info = nullptr;     // for run-time errors
    std::uint8_t leaf = kNotLeaf;       // lets parents read leaves without a call

    static constexpr std::uint8_t kNotLeaf = 0, kConstLeaf = 1, kRayLeaf = 2, kModArgLeaf = 3,
                                  kParamLeaf = 4, kVarLeaf = 5;

    double operator()(EvalState& s) const { return fn(*this, s); }
};

// Mutable per-thread evaluation state (owned by an Evaluator, or by the linker while
// folding constants).
struct EvalState {
    const RayContext* ray = nullptr;
    double* varValue = nullptr;
    std::uint64_t* varStamp = nullptr;
    std::uint64_t clock = 1;
    double* argStack = nullptr;
    int argTop = 0;
    int argCapacity = 0;
    const double* frame = nullptr;  // current function's arguments
    int frameSize = 0;
    const FunctionInfo* const* functions = nullptr;  // for function-valued parameters
    const char* stackStart = nullptr;
    int depth = 0;
    long mathErrors = 0;
};

// Evaluates an operand. Leaves (about half of all nodes) are read inline: a predictable
// branch is cheaper than an indirect call. Out-of-range arguments fall through to the
// node's function, which reports the error.
inline double eval(const Node* k, EvalState& s) {
    switch (k->leaf) {
        case Node::kConstLeaf: return k->num;
        case Node::kRayLeaf: return rayValue(*s.ray, k->index);
        case Node::kModArgLeaf:
            if (static_cast<std::size_t>(k->index - 1) < s.ray->args.size())
                return s.ray->args[k->index - 1];
            break;
        case Node::kParamLeaf:
            if (k->index >= 1 && k->index <= s.frameSize) return s.frame[k->index - 1];
            break;
        case Node::kVarLeaf:  // a variable already computed for this ray
            if (s.varStamp[k->index] == s.clock) return s.varValue[k->index];
            break;
        default: break;
    }
    return k->fn(*k, s);
}

// Sets Node::leaf from the node's function (after linking).
void classifyLeaf(Node& n);

// Calls nested deeper than this, or using more C++ stack than kMaxStackBytes, are
// reported as runaway recursion instead of overflowing the thread's stack.
constexpr int kMaxCallDepth = 20000;
constexpr long kMaxStackBytes = 512 * 1024;

// Function ids passed through function-valued parameters: user functions >= 0,
// builtins -(index + 1).
inline double builtinFunctionId(int builtinIndex) { return -(builtinIndex + 1.0); }

// Evaluation functions, one per node kind (eval.cpp).
double evConst(const Node&, EvalState&);
double evRay(const Node&, EvalState&);
double evModArg(const Node&, EvalState&);      // index = n (constant)
double evModArgDyn(const Node&, EvalState&);   // a = n
double evParam(const Node&, EvalState&);       // index = 1-based parameter
double evParamDyn(const Node&, EvalState&);    // arg(n) inside a function, a = n
double evVar(const Node&, EvalState&);         // ptr = VarInfo
double evNeg(const Node&, EvalState&);
double evAdd(const Node&, EvalState&);
double evSub(const Node&, EvalState&);
double evMul(const Node&, EvalState&);
double evAddC(const Node&, EvalState&);        // a + num
double evSubC(const Node&, EvalState&);        // a - num
double evCSub(const Node&, EvalState&);        // num - a
double evMulC(const Node&, EvalState&);        // a * num
double evDiv(const Node&, EvalState&);
double evPow(const Node&, EvalState&);
double evPowInt(const Node&, EvalState&);      // index = integer exponent
double evMath1(const Node&, EvalState&);       // ptr = Builtin with f1
double evBuiltinN(const Node&, EvalState&);    // ptr = Builtin with fn, kids
double evIf(const Node&, EvalState&);
double evSelect(const Node&, EvalState&);      // kids[0] = index
double evCallUser(const Node&, EvalState&);    // ptr = FunctionInfo, kids
double evCallParamFn(const Node&, EvalState&); // index = parameter holding a function id
double evError(const Node&, EvalState&);       // info->text is the message

// Arithmetic shared by evaluation and constant folding. RADIANCE compat (calexpr.c,
// calfunc.c): division by zero, a bad power and a library call with a non-finite result
// give 0, counted in EvalState::mathErrors, instead of stopping the run.
double divide(double x, double y, EvalState& s);
double power(double x, double y, EvalState& s);
double powerInt(double x, int n, EvalState& s);

// Calls a user function with arguments already evaluated (Evaluator::call, function
// parameters). `site` names the call for errors; may be null.
double callUser(const FunctionInfo& f, const double* args, int nargs, EvalState& s,
                const NodeInfo* site);
// Calls any function by id (see builtinFunctionId).
double callById(double id, const double* args, int nargs, EvalState& s, const NodeInfo* site);

}  // namespace rp::calc
