// rcontrib's binning (RADIANCE rcontrib.1, rcmain.c, rcontrib.c addmodifier/trace_contrib):
// the modifiers to track with the -p, -b and -bn in effect where each -m/-M stands, the
// -e/-f definitions, the options that read them, and the bin expressions compiled once and
// evaluated per ray. rcontrib bins what its rays meet with it (render/rcontrib.h); mkpmap
// bins the photons of a precomputed contribution map with the same (precomp_contrib.h),
// so that both agree on every bin.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "calc/program.h"
#include "util/options.h"
#include "util/vec.h"
#include "util/warnings.h"

namespace rp::pmap {

// One modifier to track (-m name, or a word of a -M file), with the most recent -o, -p,
// -b and -bn to its left.
struct ContribModifier {
    std::string name;
    std::string outSpec;        // -o: "" = standard output (rcontrib only)
    std::string params;         // -p "a=1,b=2" ("" = none)
    std::string binExpr = "0";  // -b (RADIANCE: "0", a single bin, unless given)
    int bins = 1;               // -bn, or 1 for a constant bin expression
};

// A -e expression or -f file, in command-line order.
struct CalcDefinition {
    bool file = false;  // true: `text` names a .cal file
    std::string text;
};

// Whether a -b expression is a plain number (one bin, no evaluation per ray).
bool isConstantBin(const std::string& expr);

// Evaluates a -bn value: the definitions so far, then `expr` (rcmain.c eval). Throws
// InputError if it does not evaluate.
double evalBinCount(const std::vector<CalcDefinition>& defs, const std::string& expr);
using BinCountEval = double (*)(const std::vector<CalcDefinition>& defs, const std::string& expr);

// The options -p -b -bn -m -M (and rcontrib's -o) add to a table, filling `modifiers`;
// -bn expressions see `definitions` as parsed so far. Messages as RADIANCE's: "duplicate
// modifier 'x'", "cannot track 'void' modifier", "unspecified or illegal bin count for
// modifier 'x'", "illegal non-zero constant for bin (e)", "cannot find modifier file 'f'".
class ModifierOptions {
public:
    ModifierOptions(std::vector<ContribModifier>& modifiers,
                    const std::vector<CalcDefinition>& definitions, BinCountEval eval)
        : modifiers_(modifiers), definitions_(definitions), eval_(eval) {}
    void addTo(OptionTable& t, bool withOutput);

private:
    void add(const std::string& name);
    void addFile(const std::string& file);
    int binCount(const std::string& text) const;

    std::vector<ContribModifier>& modifiers_;
    const std::vector<CalcDefinition>& definitions_;
    BinCountEval eval_;
    std::unordered_set<std::string> seen_;
    std::string out_, params_, binExpr_;
    int bins_ = 0;
};

// The bin expressions of a modifier list, compiled once (modifiers that share -p share a
// program). Throws InputError for an expression that does not evaluate, and "too many
// bins" beyond what a run can hold.
class ContribBins {
public:
    ContribBins(const std::vector<ContribModifier>& modifiers,
                const std::vector<CalcDefinition>& defs);
    ~ContribBins();

    const std::vector<ContribModifier>& modifiers() const { return modifiers_; }
    // Values per record: every modifier's bins, in modifier order (offset(m) + bin).
    size_t size() const { return size_; }
    size_t offset(size_t m) const { return offsets_[m]; }
    int bins(size_t m) const { return modifiers_[m].bins; }
    // Bin numbers past -bn met so far (reported once, at the end of a run).
    WarningCounter& badBins() const { return badBins_; }

    // One thread's evaluators.
    class Binner {
    public:
        explicit Binner(const ContribBins& bins);
        ~Binner();
        // RADIANCE compat (rcontrib.c trace_contrib): the bin of modifier m for a ray at
        // `point` travelling `dir`: the value rounds to the nearest bin, negatives are
        // dropped silently (-1) and bins past -bn with a count in badBins() (-1).
        int bin(size_t m, const Vec3& point, const Vec3& dir);

    private:
        const ContribBins& owner_;
        std::vector<calc::Evaluator> evaluators_;  // one per program
    };

private:
    struct Expr {
        int program = -1;  // -1: constant bin 0
        calc::Entry entry;
    };
    std::vector<ContribModifier> modifiers_;
    std::vector<size_t> offsets_;
    size_t size_ = 0;
    std::vector<Expr> exprs_;  // per modifier
    std::vector<std::shared_ptr<const calc::Program>> programs_;
    mutable WarningCounter badBins_{"bad bin numbers (ignored)"};
};

}  // namespace rp::pmap
