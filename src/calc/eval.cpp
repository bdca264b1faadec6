// Evaluation functions for compiled .cal nodes. Hot paths (constants, ray variables,
// cached variables, arithmetic) are a single indirect call each; errors build their
// message only when thrown.
#include "calc/eval.h"

#include <cmath>
#include <string>

#include "calc/builtins.h"

namespace rp::calc {
namespace {

[[noreturn]] void runtimeError(const NodeInfo* info, const std::string& msg) {
    if (info) throw InputError(info->loc, msg);
    throw InputError(msg);
}

double finiteOrZero(double r, EvalState& s) {
    if (std::isfinite(r)) [[likely]]
        return r;
    ++s.mathErrors;
    return 0;
}

// Guards both recursion depth and real stack use: a deep chain of variables is as
// dangerous as a deep chain of calls.
void enter(EvalState& s, const NodeInfo* site, const char* kind, const std::string& name) {
    char probe;
    if (++s.depth > kMaxCallDepth ||
        (s.stackStart && s.stackStart - &probe > kMaxStackBytes)) {
        runtimeError(site, std::string("recursion too deep in ") + kind + " '" + name +
                               "' (missing base case?)");
    }
}

// RADIANCE rounds argument indices: n = value + .5, truncated.
int indexOf(double v) { return static_cast<int>(v + 0.5); }

double modArg(int n, const Node& node, EvalState& s) {
    const auto& args = s.ray->args;
    if (n < 1) return static_cast<double>(args.size());
    if (static_cast<std::size_t>(n) > args.size())
        runtimeError(node.info, "missing real argument " + std::to_string(n) +
                                    " (modifier has " + std::to_string(args.size()) + ")");
    return args[n - 1];
}

double param(int n, const Node& node, EvalState& s) {
    if (n < 1) return s.frameSize;
    if (n > s.frameSize)
        runtimeError(node.info, "missing argument " + std::to_string(n) + " to function");
    return s.frame[n - 1];
}

}  // namespace

double divide(double x, double y, EvalState& s) {
    if (y == 0) {
        ++s.mathErrors;
        return 0;
    }
    return x / y;
}

double power(double x, double y, EvalState& s) { return finiteOrZero(std::pow(x, y), s); }

double powerInt(double x, int n, EvalState& s) {
    unsigned m = static_cast<unsigned>(n < 0 ? -n : n);
    double r = 1, b = x;
    while (m) {
        if (m & 1) r *= b;
        b *= b;
        m >>= 1;
    }
    return n < 0 ? finiteOrZero(1 / r, s) : finiteOrZero(r, s);
}

double evConst(const Node& n, EvalState&) { return n.num; }
double evRay(const Node& n, EvalState& s) { return rayValue(*s.ray, n.index); }
double evModArg(const Node& n, EvalState& s) { return modArg(n.index, n, s); }
double evModArgDyn(const Node& n, EvalState& s) { return modArg(indexOf(eval(n.a, s)), n, s); }
double evParam(const Node& n, EvalState& s) { return param(n.index, n, s); }
double evParamDyn(const Node& n, EvalState& s) { return param(indexOf(eval(n.a, s)), n, s); }

double evVar(const Node& n, EvalState& s) {
    const int slot = n.index;
    if (s.varStamp[slot] == s.clock) return s.varValue[slot];
    const auto* var = static_cast<const VarInfo*>(n.ptr);
    // No frame switch needed: a variable's body never reads function parameters (the
    // compiler turns arg(n) there into the modifier's argument).
    if (++s.depth > 64) {  // full check only when nesting gets deep
        --s.depth;
        enter(s, n.info, "variable", var->name);
    }
    double v = eval(var->body, s);
    --s.depth;
    s.varValue[slot] = v;
    s.varStamp[slot] = s.clock;
    return v;
}

double evNeg(const Node& n, EvalState& s) { return -eval(n.a, s); }
double evAdd(const Node& n, EvalState& s) { return eval(n.a, s) + eval(n.b, s); }
double evSub(const Node& n, EvalState& s) { return eval(n.a, s) - eval(n.b, s); }
double evMul(const Node& n, EvalState& s) { return eval(n.a, s) * eval(n.b, s); }
double evAddC(const Node& n, EvalState& s) { return eval(n.a, s) + n.num; }
double evSubC(const Node& n, EvalState& s) { return eval(n.a, s) - n.num; }
double evCSub(const Node& n, EvalState& s) { return n.num - eval(n.a, s); }
double evMulC(const Node& n, EvalState& s) { return eval(n.a, s) * n.num; }
double evDiv(const Node& n, EvalState& s) {
    double x = eval(n.a, s);
    return divide(x, eval(n.b, s), s);
}
double evPow(const Node& n, EvalState& s) {
    double x = eval(n.a, s);
    return power(x, eval(n.b, s), s);
}
double evPowInt(const Node& n, EvalState& s) { return powerInt(eval(n.a, s), n.index, s); }

double evMath1(const Node& n, EvalState& s) {
    const auto* b = static_cast<const Builtin*>(n.ptr);
    return finiteOrZero(b->f1(eval(n.a, s)), s);
}

double evBuiltinN(const Node& n, EvalState& s) {
    const auto* b = static_cast<const Builtin*>(n.ptr);
    double args[8];
    for (int i = 0; i < n.nkids; ++i) args[i] = eval(n.kids[i], s);
    return finiteOrZero(b->fn(args, n.nkids), s);
}

double evIf(const Node& n, EvalState& s) { return eval(n.a, s) > 0 ? eval(n.b, s) : eval(n.c, s); }

double evSelect(const Node& n, EvalState& s) {
    int k = indexOf(eval(n.kids[0], s));
    if (k == 0) return n.nkids - 1;
    if (k < 0 || k >= n.nkids)
        runtimeError(n.info, "select index " + std::to_string(k) + " out of range 1.." +
                                 std::to_string(n.nkids - 1));
    return eval(n.kids[k], s);
}

double callUser(const FunctionInfo& f, const double* args, int nargs, EvalState& s,
                const NodeInfo* site) {
    if (s.argTop + nargs > s.argCapacity)
        runtimeError(site, "recursion too deep in function '" + f.name + "' (missing base case?)");
    double* frame = s.argStack + s.argTop;
    for (int i = 0; i < nargs; ++i) frame[i] = args[i];
    const double* savedFrame = s.frame;
    int savedSize = s.frameSize, savedTop = s.argTop;
    s.argTop += nargs;
    s.frame = frame;
    s.frameSize = nargs;
    enter(s, site, "function", f.name);
    double r = eval(f.body, s);
    --s.depth;
    s.frame = savedFrame;
    s.frameSize = savedSize;
    s.argTop = savedTop;
    return r;
}

double evCallUser(const Node& n, EvalState& s) {
    const auto& f = *static_cast<const FunctionInfo*>(n.ptr);
    const int base = s.argTop, nargs = n.nkids;
    if (base + nargs > s.argCapacity)
        runtimeError(n.info, "recursion too deep in function '" + f.name + "' (missing base case?)");
    double* frame = s.argStack + base;
    // Arguments are evaluated in order; each may itself call functions that use the
    // stack above the slots filled so far.
    for (int i = 0; i < nargs; ++i) {
        double v = eval(n.kids[i], s);
        frame[i] = v;
        s.argTop = base + i + 1;
    }
    const double* savedFrame = s.frame;
    int savedSize = s.frameSize;
    s.frame = frame;
    s.frameSize = nargs;
    if (++s.depth > 64) {  // cheap depth first; full check only when nesting gets deep
        --s.depth;
        enter(s, n.info, "function", f.name);
    }
    double r = eval(f.body, s);
    --s.depth;
    s.frame = savedFrame;
    s.frameSize = savedSize;
    s.argTop = base;
    return r;
}

double callById(double id, const double* args, int nargs, EvalState& s, const NodeInfo* site) {
    if (id >= 0) return callUser(*s.functions[static_cast<int>(id)], args, nargs, s, site);
    int bi = static_cast<int>(-id) - 1;
    const Builtin& b = builtins()[bi];
    if (nargs < b.minArgs || nargs > b.maxArgs)
        runtimeError(site, "wrong number of arguments to '" + std::string(b.name) + "'");
    return finiteOrZero(b.f1 ? b.f1(args[0]) : b.fn(args, nargs), s);
}

double evCallParamFn(const Node& n, EvalState& s) {
    double id = param(n.index, n, s);
    double args[16];
    if (n.nkids > 16) runtimeError(n.info, "too many arguments through a function parameter");
    for (int i = 0; i < n.nkids; ++i) args[i] = eval(n.kids[i], s);
    return callById(id, args, n.nkids, s, n.info);
}

double evError(const Node& n, EvalState&) { runtimeError(n.info, n.info->text); }

void classifyLeaf(Node& n) {
    if (n.fn == evConst) n.leaf = Node::kConstLeaf;
    else if (n.fn == evRay) n.leaf = Node::kRayLeaf;
    else if (n.fn == evModArg && n.index >= 1) n.leaf = Node::kModArgLeaf;
    else if (n.fn == evParam && n.index >= 1) n.leaf = Node::kParamLeaf;
    else if (n.fn == evVar) n.leaf = Node::kVarLeaf;
    else n.leaf = Node::kNotLeaf;
}

}  // namespace rp::calc
