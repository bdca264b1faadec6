// rcontrib's tally (see rcontrib.h).
#include "render/rcontrib.h"

#include <atomic>
#include <cmath>
#include <map>
#include <unordered_map>

#include "calc/search_path.h"
#include "light/light_sources.h"
#include "util/error.h"
#include "util/paths.h"

namespace rp::render {

struct ContribTargets::Target {
    size_t offset = 0;
    int bins = 1;
    int program = -1;  // index into programs(); -1: constant bin 0
    calc::Entry expr;
    bool constant() const { return program < 0; }
};

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

std::atomic<bool> warnedPhotonBins{false};

constexpr size_t kMaxValues = size_t(50) << 20;  // 1.2 GB of RGB doubles

}  // namespace

std::vector<PhotonSource> contributionSources(const Scene& scene, const SceneGeometry& geometry) {
    std::vector<PhotonSource> out;
    for (const light::LightSource& s : light::findLightSources(scene, geometry))
        out.push_back({scene.prims[size_t(s.material)].name, s.params.radiance, s.distant()});
    return out;
}

double evalBinCount(const std::vector<CalcDefinition>& defs, const std::string& expr) {
    calc::Builder b = definitionsBuilder(defs);
    int id = b.addExpression(expr, SourceLoc{"-bn", 0});
    auto prog = b.build();
    return tryEval(prog, prog->expression(id));
}

ContribTargets::ContribTargets(const Scene& scene, const std::vector<ContribModifier>& modifiers,
                               const std::vector<CalcDefinition>& defs, bool contributions,
                               const std::vector<PhotonSource>& photonSources)
    : modifiers_(modifiers), photonSources_(photonSources), contributions_(contributions) {
    std::unordered_map<std::string, const Target*> byName;
    // Modifiers that share parameters share one program (a -M list of hundreds of lamps
    // with one -p and -b compiles once).
    std::map<std::string, int> programOf;
    std::vector<calc::Builder> builders;
    std::vector<std::pair<int, int>> pending;  // (target, expression id)
    for (const ContribModifier& m : modifiers_) {
        auto t = std::make_unique<Target>();
        t->offset = size_;
        t->bins = m.bins;
        offsets_.push_back(size_);
        size_ += size_t(m.bins);
        // Each thread keeps every bin, and each ray of a batch too: beyond this a run
        // would exhaust memory rather than compute.
        if (size_ > kMaxValues)
            throw InputError("too many bins: " + std::to_string(size_) +
                             " over all modifiers (at most " + std::to_string(kMaxValues) + ")");
        if (!isConstantBin(m.binExpr)) {
            auto [it, fresh] = programOf.try_emplace(m.params, int(builders.size()));
            if (fresh) {
                builders.push_back(definitionsBuilder(defs));
                if (!m.params.empty()) builders.back().loadString(paramDefinitions(m.params), "-p");
            }
            t->program = it->second;
            pending.emplace_back(int(targets_.size()),
                                 builders[size_t(t->program)].addExpression(
                                     m.binExpr, SourceLoc{"-b " + m.binExpr, 0}));
        }
        byName[m.name] = t.get();
        targets_.push_back(std::move(t));
    }
    for (const calc::Builder& b : builders) programs_.push_back(b.build());
    for (auto [target, id] : pending) {
        Target& t = *targets_[size_t(target)];
        t.expr = programs_[size_t(t.program)]->expression(id);
        tryEval(programs_[size_t(t.program)], t.expr);
    }
    // RADIANCE compat (rcontrib.c trace_contrib): a surface is tracked by the name of its
    // own modifier.
    byModifier_.assign(scene.prims.size(), nullptr);
    for (size_t i = 0; i < scene.prims.size(); ++i) {
        auto it = byName.find(scene.prims[i].name);
        if (it != byName.end()) byModifier_[i] = it->second;
    }
    // pmcontrib2.c: photons by the name of their source's light material.
    bool any = photonSources.empty();
    for (const PhotonSource& s : photonSources) {
        auto it = byName.find(s.material);
        bySource_.push_back(it != byName.end() ? it->second : nullptr);
        any = any || bySource_.back();
    }
    if (!any) throw InputError("modifiers not in photon map");
}

ContribTargets::~ContribTargets() = default;

ContribTally::ContribTally(const ContribTargets& targets)
    : targets_(targets), values_(targets.size()) {
    for (const auto& p : targets.programs()) evaluators_.emplace_back(p);
}

ContribTally::~ContribTally() = default;

void ContribTally::reset() { std::fill(values_.begin(), values_.end(), Color{}); }

int ContribTally::bin(const ContribTargets::Target& t, const Vec3& point, const Vec3& dir) {
    if (t.constant()) return 0;
    // RADIANCE compat (rcontrib.c trace_contrib): world coordinates of the hit and the
    // ray's direction; the value rounds to the nearest bin, negatives are dropped
    // silently and bins past -bn with a warning.
    calc::RayContext ray;
    ray.P = point;
    ray.D = dir;
    calc::Evaluator& ev = evaluators_[size_t(t.program)];
    ev.setRay(ray);
    const double v = ev.eval(t.expr);
    if (!(v > -0.5)) return -1;
    const double b = std::floor(v + 0.5);
    if (b >= t.bins) {
        targets_.badBins().add();
        return -1;
    }
    return int(b);
}

void ContribTally::add(int32_t modifier, const Vec3& point, const Vec3& dir, const Color& coef,
                       const Color& value) {
    const ContribTargets::Target* t = targets_.targetOfModifier(modifier);
    if (!t) return;
    const int b = bin(*t, point, dir);
    if (b < 0) return;
    values_[t->offset + size_t(b)] += targets_.contributions() ? coef * value : coef;
}

void ContribTally::addPhotons(int32_t source, const PhotonOrigin* origin, const Color& value) {
    const ContribTargets::Target* t = targets_.targetOfSource(source);
    if (!t) return;
    const PhotonSource& src = targets_.photonSource(source);
    int b = 0;
    if (!t->constant()) {
        if (!origin) {
            // RADIANCE compat (pmcontrib2.c, default build): a map without primary rays
            // cannot place a photon in a bin. RADIANCE warns (its advice is to rebuild
            // RADIANCE; ours is mkpmap -apCPD) and drops the photon: its dummy ray meets
            // no source, except a full-sky one, whose photons all land in the bin of
            // D = 0. We drop those too.
            if (!warnedPhotonBins.exchange(true)) {
                warn(
                    "no photon primary hitpoints for bin evaluation; using dummy (0,0,0)!"
                    " (make the map with mkpmap -apCPD)");
                warn("no photon primary directions for bin evaluation; using dummy (0,0,0)!");
            }
            return;
        }
        // pmcontrib2.c with primary rays: the direction back toward the source; the point
        // where the photon left it (RADIANCE gives a distant source's P as 0, and a local
        // one's where its ray toward the source meets it, from the position of the photon
        // emitted before, a slip we do not copy).
        b = bin(*t, src.distant ? Vec3{} : origin->point, origin->toSource);
        if (b < 0) return;
    }
    Color v = value;
    if (!targets_.contributions()) {
        // Coefficients: per unit radiance of the source (0 where it emits nothing).
        const Color& r = src.radiance;
        v = Color{r.r != 0 ? v.r / r.r : 0, r.g != 0 ? v.g / r.g : 0, r.b != 0 ? v.b / r.b : 0};
    }
    values_[t->offset + size_t(b)] += v;
}

}  // namespace rp::render
