// User functions for the function-driven generators (genrev, gensurf, genworm): the
// -e/-f definitions plus the command-line expressions wrapped as calc functions of t (or
// s,t), compiled once and called per sample point. Parsing each generator's command line
// and writing its output live in genrev.h, gensurf.h and genworm.h.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "calc/program.h"
#include "util/options.h"

namespace rp::gen {

// One -e or -f option, kept in command-line order (later definitions replace earlier).
struct CalcSource {
    enum class Kind { Expression, File };
    Kind kind = Kind::Expression;
    std::string text;  // the expression, or the file name looked up along the search path
};

// Handle of a function defined with GenFunctions::define().
struct GenFunctionId {
    int index = -1;
};

// RADIANCE's generators (genrev.c, gensurf.c, genworm.c) predefine PI and the curve
// functions hermite, bezier and bspline, then compile -e/-f in order, then the
// command-line expressions as "X`SYS(s,t) = <expr>". We do the same through calc: the
// prelude is .cal text (hermite is already a calc builtin), the expressions become
// functions under names no user file can reach by accident.
class GenFunctions {
public:
    // Loads the prelude and every source. Throws InputError for a syntax error (naming
    // "-e" or the file and line) or a file not found along `searchPath`.
    GenFunctions(const std::vector<CalcSource>& sources, std::vector<std::string> searchPath);

    // Wraps `body` as a function of `params` ("t" or "s,t"); `label` names the command-line
    // argument in errors ("z(t): syntax error: ..."). Call before build().
    GenFunctionId define(const std::string& label, const std::string& params,
                         const std::string& body);

    // Compiles everything. Undefined names are reported when first evaluated.
    void build();

    // Whether the user defined `name` as a function of exactly `nparams` arguments
    // (gensurf's valid(s,t)); its handle when so. Only after build().
    bool userFunction(const std::string& name, int nparams, GenFunctionId& id);

    // Calls a defined function. Throws InputError for undefined names it uses.
    double call(GenFunctionId id, std::span<const double> args);
    double call(GenFunctionId id, double t) { return call(id, std::span<const double>(&t, 1)); }
    double call(GenFunctionId id, double s, double t) {
        const double st[2] = {s, t};
        return call(id, std::span<const double>(st, 2));
    }

    // Divisions by zero and invalid library calls so far (calc evaluates each as 0).
    long mathErrors() const;

    // The warning a tool prints when mathErrors() > 0 (empty otherwise).
    std::string mathWarning() const;

private:
    calc::Builder builder_;
    std::vector<std::string> names_;  // internal function name per GenFunctionId
    std::shared_ptr<const calc::Program> program_;
    std::unique_ptr<calc::Evaluator> evaluator_;
    std::vector<calc::Function> functions_;  // resolved after build(), per GenFunctionId
};

// Adds the .cal options of genrev, gensurf and genworm to their table: -e expr and
// -f file go to `sources`, in order.
void addCalcOptions(OptionTable& table, std::vector<CalcSource>& sources);

}  // namespace rp::gen
