// Intermediate form of .cal code between parsing and code generation: a tree of Nodes
// with every name already resolved (variable slots, parameter indices, ray-variable
// offsets, callee pointers). The linker (compile.cpp) builds, folds and inlines it;
// codegen.cpp turns it into VM code (vm.h). Nothing here is evaluated directly.
// Internal to the calc module; users see program.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "util/error.h"

namespace rp::calc {

// Where a node came from and what to say if it fails at run time.
struct NodeInfo {
    SourceLoc loc;
    std::string text;  // name or complete error message
};

struct Node;

struct VarInfo {
    std::string name;
    int slot = 0;
    const Node* body = nullptr;
    SourceLoc loc;
};

struct FunctionInfo {
    std::string name;
    int index = 0;  // position in Program's function table
    int nparams = 0;
    bool constant = false;  // defined with ':'
    bool pure = false;      // body depends only on its parameters
    std::vector<bool> paramCalled;
    const Node* body = nullptr;
    SourceLoc loc;
};

// Node kinds. Each kind is a unique tag object; Node::fn points at one of them.
enum class Op : std::uint8_t {
    Const,
    Ray,
    ModArg,
    ModArgDyn,
    Param,
    ParamDyn,
    Var,
    Neg,
    Add,
    Sub,
    Mul,
    AddC,
    SubC,
    CSub,
    MulC,
    Div,
    Pow,
    PowInt,
    Math1,
    BuiltinN,
    If,
    Select,
    CallUser,
    CallParamFn,
    Chan,
    Error
};
struct NodeKind {
    Op op;
};

inline constexpr NodeKind evConst{Op::Const};          // num
inline constexpr NodeKind evRay{Op::Ray};              // index = byte offset in RayContext
inline constexpr NodeKind evModArg{Op::ModArg};        // index = n (constant)
inline constexpr NodeKind evModArgDyn{Op::ModArgDyn};  // a = n
inline constexpr NodeKind evParam{Op::Param};          // index = 1-based parameter
inline constexpr NodeKind evParamDyn{Op::ParamDyn};    // arg(n) inside a function, a = n
inline constexpr NodeKind evVar{Op::Var};              // index = slot, ptr = VarInfo
inline constexpr NodeKind evNeg{Op::Neg};
inline constexpr NodeKind evAdd{Op::Add};
inline constexpr NodeKind evSub{Op::Sub};
inline constexpr NodeKind evMul{Op::Mul};
inline constexpr NodeKind evAddC{Op::AddC};  // a + num
inline constexpr NodeKind evSubC{Op::SubC};  // a - num
inline constexpr NodeKind evCSub{Op::CSub};  // num - a
inline constexpr NodeKind evMulC{Op::MulC};  // a * num
inline constexpr NodeKind evDiv{Op::Div};
inline constexpr NodeKind evPow{Op::Pow};
inline constexpr NodeKind evPowInt{Op::PowInt};      // index = integer exponent
inline constexpr NodeKind evMath1{Op::Math1};        // ptr = Builtin with f1
inline constexpr NodeKind evBuiltinN{Op::BuiltinN};  // ptr = Builtin with fn, kids
inline constexpr NodeKind evIf{Op::If};
inline constexpr NodeKind evSelect{Op::Select};      // kids[0] = index
inline constexpr NodeKind evCallUser{Op::CallUser};  // ptr = FunctionInfo, kids
inline constexpr NodeKind evCallParamFn{
    Op::CallParamFn};                          // index = parameter holding a function id
inline constexpr NodeKind evChan{Op::Chan};    // input channel a ($N: index 0, in(): 1)
inline constexpr NodeKind evError{Op::Error};  // info->text is the message

struct Node {
    const NodeKind* fn = nullptr;  // the kind
    const Node* a = nullptr;
    const Node* b = nullptr;
    const Node* c = nullptr;
    const Node* const* kids = nullptr;  // calls and select: all arguments
    int nkids = 0;
    int index = 0;                   // slot, parameter, exponent, byte offset
    double num = 0;                  // constant value
    const void* ptr = nullptr;       // VarInfo, FunctionInfo, Builtin
    const NodeInfo* info = nullptr;  // for run-time errors

    Op op() const { return fn->op; }
};

// Function ids passed through function-valued parameters: user functions >= 0,
// builtins -(index + 1).
inline double builtinFunctionId(int builtinIndex) { return -(builtinIndex + 1.0); }

}  // namespace rp::calc
