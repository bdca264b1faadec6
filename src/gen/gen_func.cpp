// User functions for genrev, gensurf and genworm: prelude, -e/-f sources, wrapped
// command-line expressions, evaluation (see gen_func.h).
#include "gen/gen_func.h"

#include "util/error.h"

namespace rp::gen {

namespace {

// What RADIANCE's generators predefine (genrev.c/gensurf.c/genworm.c main(): varset PI,
// funset hermite/bezier/bspline). hermite is a calc builtin already; the other two are
// the cubic Bezier and uniform B-spline bases in the same argument order
// (p1, p2, p3, p4, t).
constexpr const char* kPrelude =
    "PI = 3.14159265358979323846;\n"
    "bezier(p1, p2, p3, p4, t) = p1 * (1 + t*(-3 + t*(3 - t))) + p2 * 3*t*(1 + t*(-2 + t))"
    " + p3 * 3*t*t*(1 - t) + p4 * t*t*t;\n"
    "bspline(p1, p2, p3, p4, t) = p1 * (1/6 + t*(-1/2 + t*(1/2 - 1/6*t)))"
    " + p2 * (2/3 + t*t*(-1 + 1/2*t)) + p3 * (1/6 + t*(1/2 + t*(1/2 - 1/2*t)))"
    " + p4 * (1/6*t*t*t);\n";

}  // namespace

GenFunctions::GenFunctions(const std::vector<CalcSource>& sources,
                           std::vector<std::string> searchPath)
    : builder_(std::move(searchPath)) {
    builder_.loadString(kPrelude, "generator prelude");
    for (const CalcSource& src : sources) {
        if (src.kind == CalcSource::Kind::File)
            builder_.loadFile(src.text);
        else
            builder_.loadString(src.text, "-e '" + src.text + "'", 0);  // line 0: no ":1"
    }
}

GenFunctionId GenFunctions::define(const std::string& label, const std::string& params,
                                   const std::string& body) {
    RP_CHECK(program_ == nullptr);
    // A name with a context mark in the middle cannot be written by accident in a .cal
    // file meant for rendering (RADIANCE uses "Z`SYS" the same way).
    std::string name = "F" + std::to_string(names_.size()) + "`SYS";
    if (body.find_first_not_of(" \t\n") == std::string::npos)
        throw InputError(label + ": empty expression");
    builder_.loadString(name + "(" + params + ") = " + body + ";", label, 0);
    names_.push_back(name);
    return GenFunctionId{static_cast<int>(names_.size()) - 1};
}

void GenFunctions::build() {
    program_ = builder_.build();
    evaluator_ = std::make_unique<calc::Evaluator>(program_);
    calc::RayContext none;
    evaluator_->setRay(none);
    for (const std::string& name : names_) {
        auto f = program_->function(name);
        RP_CHECK(f.has_value());
        functions_.push_back(*f);
    }
}

bool GenFunctions::userFunction(const std::string& name, int nparams, GenFunctionId& id) {
    RP_CHECK(program_ != nullptr);
    auto f = program_->function(name);
    // Builtins have negative ids (calc/ir.h builtinFunctionId); only user definitions count.
    if (!f || f->nparams != nparams || f->id < 0) return false;
    functions_.push_back(*f);
    names_.push_back(name);
    id.index = static_cast<int>(functions_.size()) - 1;
    return true;
}

double GenFunctions::call(GenFunctionId id, std::span<const double> args) {
    RP_CHECK(evaluator_ != nullptr && id.index >= 0 &&
             id.index < static_cast<int>(functions_.size()));
    return evaluator_->call(functions_[id.index], args);
}

long GenFunctions::mathErrors() const { return evaluator_ ? evaluator_->mathErrors() : 0; }

std::string GenFunctions::mathWarning() const {
    long n = mathErrors();
    if (n == 0) return {};
    return "warning: " + std::to_string(n) +
           (n == 1 ? " division by zero or invalid math call"
                   : " divisions by zero or invalid math calls") +
           " evaluated as 0";
}

void addCalcOptions(OptionTable& table, std::vector<CalcSource>& sources) {
    for (const char* name : {"-e", "-f"}) {
        const CalcSource::Kind kind =
            name[1] == 'e' ? CalcSource::Kind::Expression : CalcSource::Kind::File;
        table.add(customOption(name, [&sources, kind](OptionReader& r) {
            sources.push_back({kind, r.word()});
        }));
    }
}

}  // namespace rp::gen
