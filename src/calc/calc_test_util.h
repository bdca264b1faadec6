// Helpers shared by the calc unit tests: build a Program from inline text (optionally
// after the project's rayinit.cal) and evaluate one expression.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "calc/program.h"

namespace rp::calc::testing {

inline std::string libDir() { return std::string(RP_SOURCE_DIR) + "/lib"; }

// Evaluates `expr` after loading `defs` (and rayinit.cal when `rayinit`).
inline double evalWith(std::string_view defs, std::string_view expr, bool rayinit = true,
                       const RayContext* ray = nullptr) {
    Builder b({libDir()});
    if (rayinit) b.loadFile("rayinit.cal");
    b.loadString(defs, "defs.cal");
    int id = b.addExpression(expr, SourceLoc{"expr", 1});
    auto prog = b.build();
    Evaluator ev(prog);
    RayContext none;
    ev.setRay(ray ? *ray : none);
    return ev.eval(prog->expression(id));
}

}  // namespace rp::calc::testing
