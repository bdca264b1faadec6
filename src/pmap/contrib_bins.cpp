// rcontrib's binning, shared with mkpmap's precomputed contributions (contrib_bins.h).
#include "pmap/contrib_bins.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <unordered_map>

#include "calc/search_path.h"
#include "util/command_args.h"
#include "util/dir_code.h"
#include "util/error.h"
#include "util/paths.h"

namespace rp::pmap {

namespace {

// RADIANCE compat (rcmain.c): initfunc loads rayinit.cal before the user's definitions.
calc::Builder definitionsBuilder(const std::vector<CalcDefinition>& defs) {
    calc::Builder b(calc::defaultSearchPath(projectLibDir()));
    b.loadFile("rayinit.cal");
    for (const CalcDefinition& d : defs) {
        if (d.file)
            b.loadFile(d.text);
        else
            b.loadString(d.text);
    }
    return b;
}

// -p "a=1,b=2:c=3;d=4" as definitions (RADIANCE set_eparams: commas, colons or
// semicolons separate the assignments).
std::string paramDefinitions(const std::string& params) {
    std::string s;
    for (char c : params) s += (c == ',' || c == ':') ? ';' : c;
    if (!s.empty() && s.back() != ';') s += ';';
    return s;
}

// Evaluates `e` once on a ray at the origin looking up: a bin expression that cannot be
// evaluated is reported before any ray is traced.
double tryEval(const std::shared_ptr<const calc::Program>& prog, calc::Entry e) {
    calc::Evaluator ev(prog);
    calc::RayContext ray;
    ev.setRay(ray);
    return ev.eval(e);
}

constexpr size_t kMaxValues = size_t(50) << 20;  // 1.2 GB of RGB doubles

}  // namespace

bool isConstantBin(const std::string& e) {
    char* end = nullptr;
    std::strtod(e.c_str(), &end);
    while (*end == ' ' || *end == '\t') ++end;
    return !e.empty() && *end == '\0';
}

double evalBinCount(const std::vector<CalcDefinition>& defs, const std::string& expr) {
    calc::Builder b = definitionsBuilder(defs);
    int id = b.addExpression(expr, SourceLoc{"-bn", 0});
    auto prog = b.build();
    return tryEval(prog, prog->expression(id));
}

// ---- options ----

void ModifierOptions::addTo(OptionTable& t, bool withOutput) {
    if (withOutput) t.add(valueOption("-o", out_));
    t.add(valueOption("-p", params_));
    t.add(valueOption("-b", binExpr_));
    t.add(customOption("-bn", [this](OptionReader& r) { bins_ = binCount(r.word()); }));
    t.add(customOption("-m", [this](OptionReader& r) { add(r.word()); }));
    t.add(customOption("-M", [this](OptionReader& r) { addFile(r.word()); }));
}

// A number, or (RADIANCE rcmain.c: eval) an expression of what -e/-f defined so far.
int ModifierOptions::binCount(const std::string& text) const {
    const std::optional<double> number = parseReal(text);
    double v = number ? *number : 0;
    if (!number) {
        if (!eval_) throw InputError("bad bin count '" + text + "'");
        // RADIANCE compat (rcmain.c): the -p values in effect count (-f reinhartb.cal
        // -p MF=2 -bn Nrbins gives 577 bins).
        std::vector<CalcDefinition> defs = definitions_;
        if (!params_.empty()) defs.push_back({false, paramDefinitions(params_)});
        v = eval_(defs, text);
    }
    if (!std::isfinite(v) || std::fabs(v) > 1e9) throw InputError("bad bin count '" + text + "'");
    return int(v + 0.5);
}

void ModifierOptions::add(const std::string& name) {
    // RADIANCE compat (rcontrib.c addmodifier): messages and the constant-bin rule.
    if (!seen_.insert(name).second) throw InputError("duplicate modifier '" + name + "'");
    if (name == "void") throw InputError("cannot track 'void' modifier");
    ContribModifier m;
    m.name = name;
    m.outSpec = out_;
    m.params = params_;
    m.binExpr = binExpr_.empty() ? "0" : binExpr_;
    if (isConstantBin(m.binExpr)) {
        if (int(std::strtod(m.binExpr.c_str(), nullptr) + 1.5) != 1)
            throw InputError("illegal non-zero constant for bin (" + m.binExpr + ")");
        m.bins = 1;
    } else if (bins_ <= 0) {
        throw InputError("unspecified or illegal bin count for modifier '" + name + "'");
    } else {
        m.bins = bins_;
    }
    modifiers_.push_back(std::move(m));
}

void ModifierOptions::addFile(const std::string& file) {
    const auto dirs = calc::defaultSearchPath(projectLibDir());
    auto path = calc::findFile(file, dirs);
    if (!path) throw InputError("cannot find modifier file '" + file + "'");
    std::ifstream in(*path);
    if (!in) throw InputError("cannot load modifier file '" + *path + "'");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // RADIANCE fgetword: white-space separated words, quotes allowed.
    for (const std::string& w : splitWords(text)) add(w);
}

// ---- compiled bins ----

ContribBins::ContribBins(const std::vector<ContribModifier>& modifiers,
                         const std::vector<CalcDefinition>& defs)
    : modifiers_(modifiers) {
    // Modifiers that share parameters share one program (a -M list of hundreds of lamps
    // with one -p and -b compiles once).
    std::map<std::string, int> programOf;
    std::vector<calc::Builder> builders;
    std::vector<int> ids(modifiers_.size(), -1);
    for (size_t i = 0; i < modifiers_.size(); ++i) {
        const ContribModifier& m = modifiers_[i];
        offsets_.push_back(size_);
        size_ += size_t(m.bins);
        // Each thread keeps every bin, and each ray of a batch too: beyond this a run
        // would exhaust memory rather than compute.
        if (size_ > kMaxValues)
            throw InputError("too many bins: " + std::to_string(size_) +
                             " over all modifiers (at most " + std::to_string(kMaxValues) + ")");
        Expr e;
        if (!isConstantBin(m.binExpr)) {
            auto [it, fresh] = programOf.try_emplace(m.params, int(builders.size()));
            if (fresh) {
                builders.push_back(definitionsBuilder(defs));
                if (!m.params.empty()) builders.back().loadString(paramDefinitions(m.params), "-p");
            }
            e.program = it->second;
            ids[i] = builders[size_t(e.program)].addExpression(m.binExpr,
                                                               SourceLoc{"-b " + m.binExpr, 0});
        }
        exprs_.push_back(e);
    }
    for (const calc::Builder& b : builders) programs_.push_back(b.build());
    for (size_t i = 0; i < exprs_.size(); ++i) {
        Expr& e = exprs_[i];
        if (e.program < 0) continue;
        e.entry = programs_[size_t(e.program)]->expression(ids[i]);
        tryEval(programs_[size_t(e.program)], e.entry);
    }
}

ContribBins::~ContribBins() = default;

ContribBins::Binner::Binner(const ContribBins& bins) : owner_(bins) {
    for (const auto& p : bins.programs_) evaluators_.emplace_back(p);
}

ContribBins::Binner::~Binner() = default;

int ContribBins::Binner::bin(size_t m, const Vec3& point, const Vec3& dir) {
    const int b = binOrPastEnd(m, point, dir);
    if (b == kPastEnd) {
        owner_.badBins_.add();
        return -1;
    }
    return b;
}

int ContribBins::Binner::binOrPastEnd(size_t m, const Vec3& point, const Vec3& dir) {
    const Expr& e = owner_.exprs_[m];
    if (e.program < 0) return 0;
    calc::RayContext ray;
    ray.P = point;
    ray.D = dir;
    calc::Evaluator& ev = evaluators_[size_t(e.program)];
    ev.setRay(ray);
    const double v = ev.eval(e.entry);
    if (!(v > -0.5)) return -1;
    const double b = std::floor(v + 0.5);
    if (b >= owner_.modifiers_[m].bins) return kPastEnd;
    return int(b);
}

// ---- photons' bins by primary ----

namespace {

// What PrimaryBins needs to bin one primary.
struct PrimaryInputs {
    const ContribBins& bins;
    std::span<const ContribSource> sources;
    std::vector<int> modifierOf;  // per source: its tracked modifier, -1 none
    std::vector<bool> constant;   // per modifier: a constant bin (no expression)
    std::span<const PhotonPrimary> primaries;
    std::span<const PrimaryRay> rays;
};

// Primary i's value index, or PrimaryBins' code for where its photons go instead.
int32_t primarySlot(const PrimaryInputs& in, ContribBins::Binner& binner, size_t i) {
    const int src = in.primaries[i].srcIdx;
    if (src < 0 || size_t(src) >= in.sources.size()) return PrimaryBins::kUntracked;
    const int m = in.modifierOf[size_t(src)];
    if (m < 0) return PrimaryBins::kUntracked;
    const size_t offset = in.bins.offset(size_t(m));
    if (in.constant[size_t(m)]) return int32_t(offset);
    if (in.rays.empty()) return PrimaryBins::kNoRay;
    // pmcontrib2.c with primary rays: the direction back toward the source, and the point
    // where the photon left it (RADIANCE gives a distant source's P as 0, and a local
    // one's where its ray toward the source meets it, from the position of the photon
    // emitted before, a slip we do not copy).
    const PrimaryRay& ray = in.rays[i];
    const std::array<double, 3> d = decodeDirection(ray.dir);
    const Vec3 at =
        in.sources[size_t(src)].distant ? Vec3{} : Vec3{ray.pos[0], ray.pos[1], ray.pos[2]};
    const int b = binner.binOrPastEnd(size_t(m), at, Vec3{d[0], d[1], d[2]});
    if (b == ContribBins::Binner::kPastEnd) return PrimaryBins::kPastEnd;
    return b < 0 ? PrimaryBins::kUntracked : int32_t(offset + size_t(b));
}

}  // namespace

PrimaryBins::PrimaryBins(const ContribBins& bins, std::span<const ContribSource> sources,
                         bool contributions, std::span<const PhotonPrimary> primaries,
                         std::span<const PrimaryRay> rays, int threads) {
    RP_CHECK(rays.empty() || rays.size() == primaries.size());
    PrimaryInputs in{bins, sources, {}, {}, primaries, rays};
    for (const ContribModifier& m : bins.modifiers())
        in.constant.push_back(isConstantBin(m.binExpr));
    std::unordered_map<std::string, int> byName;
    for (size_t m = 0; m < bins.modifiers().size(); ++m) byName[bins.modifiers()[m].name] = int(m);
    for (const ContribSource& s : sources) {
        auto it = byName.find(s.material);
        in.modifierOf.push_back(it != byName.end() ? it->second : -1);
    }
    // Each primary's slot in parallel (a bin expression each), then, in place and in
    // order, its key.
    keys_.resize(primaries.size());
    tbb::task_arena arena(std::max(1, threads));
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, primaries.size(), size_t(1) << 14),
                          [&](const tbb::blocked_range<size_t>& r) {
                              ContribBins::Binner binner(bins);
                              for (size_t i = r.begin(); i != r.end(); ++i)
                                  keys_[i] = uint32_t(primarySlot(in, binner, i));
                          });
    });
    shares_.resize(1);  // key 0: untracked
    std::unordered_map<uint64_t, uint32_t> keyOf;
    for (size_t i = 0; i < primaries.size(); ++i) {
        const auto slot = int32_t(keys_[i]);
        if (slot == kUntracked) {
            keys_[i] = 0;
            continue;
        }
        const auto src = uint16_t(primaries[i].srcIdx);
        const uint64_t id = (uint64_t(uint32_t(slot)) << 16) | src;
        auto [it, added] = keyOf.try_emplace(id, uint32_t(shares_.size()));
        if (added) {
            Share sh;
            sh.slot = slot;
            if (!contributions) sh.divisor = sources[src].radiance;
            shares_.push_back(sh);
        }
        keys_[i] = it->second;
    }
    if (shares_.size() <= 256) {
        narrow_.assign(keys_.begin(), keys_.end());
        keys_ = {};
    }
}

}  // namespace rp::pmap
