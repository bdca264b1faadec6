// Parsed form of the .cal language: expression trees and definitions exactly as written,
// with source lines. Name resolution, constant folding and evaluation happen later
// (program.cpp, compile.cpp); nothing here knows about slots or ray variables.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "util/error.h"

namespace rp::calc {

struct Expr {
    enum class Kind { Number, Name, Call, Neg, Add, Sub, Mul, Div, Pow };

    Kind kind = Kind::Number;
    double number = 0;                        // Number
    std::string name;                         // Name, Call (as written, may hold '`')
    std::vector<std::unique_ptr<Expr>> kids;  // operands or call arguments
    int line = 0;                             // line of the token that starts this node
};

// One statement `name = expr;`, `name : expr;` or `name(p1, p2) = expr;`, or an output
// channel `$N = expr;` (name "$N", never qualified with a context; rcalc).
struct Definition {
    std::string name;       // fully qualified with the context it was defined in
    std::string context;    // context in effect ("" or "`a`b"), for resolving refs
    bool constant = false;  // ':' rather than '='
    bool isFunction = false;
    std::vector<std::string> params;
    std::vector<bool> paramCalled;  // params used as functions (`v1(2)` in dot(v1,v2))
    std::unique_ptr<Expr> body;     // null for an external variable (Builder::addExternal)
    SourceLoc loc;
    bool external = false;  // value supplied by the program per evaluation (rcalc's recno)
};

// "$N" names an input channel in an expression and an output channel on the left of a
// definition (calc(1), rcalc(1)).
inline bool isChannelName(const std::string& name) { return !name.empty() && name[0] == '$'; }

}  // namespace rp::calc
