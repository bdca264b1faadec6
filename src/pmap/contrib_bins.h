// rcontrib's binning (RADIANCE rcontrib.1, rcmain.c, rcontrib.c addmodifier/trace_contrib):
// the modifiers to track with the -p, -b and -bn in effect where each -m/-M stands, the
// -e/-f definitions, the options that read them, and the bin expressions compiled once and
// evaluated per ray. rcontrib bins what its rays meet with it (render/rcontrib.h); mkpmap
// bins the photons of a precomputed contribution map with the same (precomp_contrib.h),
// so that both agree on every bin.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <unordered_set>
#include <vector>

#include "calc/program.h"
#include "pmap/photon.h"
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
        // The same, with kPastEnd for a bin past -bn, not counted.
        static constexpr int kPastEnd = -2;
        int binOrPastEnd(size_t m, const Vec3& point, const Vec3& dir);

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

// A source a contribution map's primaries index (light::findLightSources order).
struct ContribSource {
    std::string material;                     // its light material's name: what -m names
    std::array<double, 3> radiance{1, 1, 1};  // -V- divides its photons' flux by this
    bool distant = false;                     // a `source`: bins see P = 0 (RADIANCE)
};

// Where the photons of a contribution map go in a record of `bins`, by their primary:
// rcontrib's binning of photons (RADIANCE pmcontrib2.c) and mkpmap's precomputed
// contributions share it. A photon's bin depends on its primary ray alone, so it is
// evaluated once per primary here, not at each of the thousand-odd photons of every
// estimate: there the bin expression and the random reads of the primaries and their rays
// took four fifths of rcontrib -ap's time.
class PrimaryBins {
public:
    // Where a primary's photons go: the value index (offset(m) + bin), or one of the
    // negative codes, and the share's divisor per channel (-V-: the source's radiance,
    // a share of 0 where it is 0; -V+: 1).
    static constexpr int32_t kUntracked = -1;  // no tracked modifier, or a negative bin
    static constexpr int32_t kPastEnd = -2;    // a bin past -bn (counted when met)
    static constexpr int32_t kNoRay = -3;      // binned by expression, and the map keeps no
                                               // primary rays (mkpmap -apC without -apCPD)
    struct Share {
        int32_t slot = kUntracked;
        std::array<double, 3> divisor{1, 1, 1};
        std::array<double, 3> of(const std::array<double, 3>& v) const {
            std::array<double, 3> out;
            for (size_t c = 0; c < 3; ++c) out[c] = divisor[c] != 0 ? v[c] / divisor[c] : 0;
            return out;
        }
    };

    // Sources by the names of the modifiers (a source whose material no modifier names is
    // untracked); `rays` empty or one per primary. Evaluated on `threads` threads; the
    // result does not depend on their number.
    PrimaryBins(const ContribBins& bins, std::span<const ContribSource> sources, bool contributions,
                std::span<const PhotonPrimary> primaries, std::span<const PrimaryRay> rays,
                int threads);
    PrimaryBins() = default;

    // The few distinct shares, and each primary's index into them.
    const std::vector<Share>& shares() const { return shares_; }
    uint32_t key(uint32_t primary) const {
        if (!narrow_.empty()) return primary < narrow_.size() ? narrow_[primary] : 0;
        return primary < keys_.size() ? keys_[primary] : 0;  // 0: untracked
    }
    const Share& share(uint32_t primary) const { return shares_[key(primary)]; }
    void prefetch(uint32_t primary) const {
        if (!narrow_.empty()) {
            if (primary < narrow_.size()) __builtin_prefetch(narrow_.data() + primary);
        } else if (primary < keys_.size()) {
            __builtin_prefetch(keys_.data() + primary);
        }
    }

private:
    // Keys by primary: in a byte each where the shares are few (a sky's 146 patches), so
    // that more of them stay in the cache for rcontrib's random reads; else in keys_.
    std::vector<uint8_t> narrow_;
    std::vector<uint32_t> keys_;
    std::vector<Share> shares_;
};

}  // namespace rp::pmap
