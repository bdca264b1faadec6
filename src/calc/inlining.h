// Which calls of user functions the linker may expand in place (compile.cpp does the
// expansion). Internal to the calc module.
#pragma once

#include "calc/ir.h"

namespace rp::calc {

// Small functions (Acos, bound, max ...) are expanded at the call site when that
// cannot change the result: each parameter is used at most once, or its argument is
// a leaf that is as cheap to re-read as a parameter slot. Arguments thereby become
// lazily evaluated, as in RADIANCE. `call` is the evCallUser node with its arguments.
bool canInline(const FunctionInfo& f, const Node* call);

}  // namespace rp::calc
