// Receivers and sender from scanned files (see flux_surfaces.h).
#include "flux/flux_surfaces.h"

#include <cmath>
#include <optional>
#include <unordered_set>

#include "util/warnings.h"

namespace rp::flux {

namespace {

// RADIANCE's default up direction for a basis whose file gives no u=.
Vec3 defaultUp(const Vec3& normal) {
    return std::fabs(normal.z) < .7 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
}

// Normalises the area-weighted normal sum and settles h= and u=, with RADIANCE's
// messages for a group without h= or without a normal.
void settleBasis(FluxGroup& g, const char* missingType, const char* undefinedNormal) {
    if (g.params.sign == 0) throw InputError(g.loc, missingType);
    if (!(length(g.normal) > 0)) throw InputError(g.loc, undefinedNormal);
    g.normal = normalize(g.normal);
    g.up = length(g.params.up) > 0 ? g.params.up : defaultUp(g.normal);
    g.basis = *basisOf(g.params.hemis);  // applyParamLine accepted only known bases
}

void finishReceiver(FluxGroup& g) {
    settleBasis(g, "missing hemisphere sampling type", "undefined normal for hemisphere sampling");
    if (g.basis == BasisKind::ShirleyChiu && g.params.size <= 1)
        throw InputError(g.params.hemisLoc, "missing size for Shirley-Chiu sampling");
    if (g.basis == BasisKind::Uniform || g.surfaces.front().type != SurfaceType::Source) return;
    // Only a whole hemisphere of sky can be cut into a basis's patches.
    for (const FluxSurface& s : g.surfaces)
        if (std::fabs(s.area - kPi) > 1e-3)
            throw InputError(s.loc, "source '" + s.name + "' must be 180-degrees");
}

void applyPending(std::vector<const ScanItem*>& pending, FluxParams& p) {
    for (const ScanItem* item : pending) applyParamLine(item->paramText, item->loc, p);
    pending.clear();
}

// A settings line is checked where it stands, though it takes effect later (RADIANCE
// reads it only then, and never when no surface follows).
void checkParams(const ScanItem& item) {
    FluxParams scratch;
    applyParamLine(item.paramText, item.loc, scratch);
}

void addSurface(FluxGroup& g, const FluxSurface& s) {
    g.surfaces.push_back(s);
    g.normal = g.normal + s.normal * s.area;
}

}  // namespace

std::vector<FluxGroup> receiversOf(const std::vector<ScanItem>& items, const std::string& file) {
    std::vector<FluxGroup> out;
    FluxParams params;  // h= lives on from receiver to receiver
    std::vector<const ScanItem*> pending;
    std::unordered_set<std::string> seen;
    std::optional<FluxGroup> cur;
    for (const ScanItem& item : items) {
        if (item.isParams) {
            checkParams(item);
            pending.push_back(&item);
            continue;
        }
        const FluxSurface& s = item.surface;
        const bool source = s.type == SurfaceType::Source;
        if (cur && source != (cur->surfaces.back().type == SurfaceType::Source))
            throw InputError(s.loc, "cannot mix source/non-source receivers");
        if (!cur || s.modifier != cur->modifier) {
            if (cur) {
                finishReceiver(*cur);
                out.push_back(std::move(*cur));
            }
            params.up = Vec3{};
            params.outSpec.reset();
            applyPending(pending, params);
            // RADIANCE's rcontrib would stop at the second -m of the name.
            if (!seen.insert(s.modifier).second)
                throw InputError(s.loc, "duplicate receiver modifier '" + s.modifier +
                                            "' (keep a receiver's surfaces together)");
            cur.emplace();
            cur->modifier = s.modifier;
            cur->loc = s.loc;
            cur->params = params;
        }
        addSurface(*cur, s);
    }
    if (!cur) throw InputError(SourceLoc{file, 0}, "missing receiver surface");
    finishReceiver(*cur);
    out.push_back(std::move(*cur));
    return out;
}

FluxGroup senderOf(const std::vector<ScanItem>& items, const std::string& file) {
    FluxGroup g;
    std::vector<const ScanItem*> pending;
    for (const ScanItem& item : items) {
        if (item.isParams) {
            checkParams(item);
            pending.push_back(&item);
            continue;
        }
        const FluxSurface& s = item.surface;
        if (s.type == SurfaceType::Source) throw InputError(s.loc, "cannot use source as a sender");
        if (g.surfaces.empty()) {
            g.modifier = s.modifier;
            g.loc = s.loc;
        } else if (s.modifier != g.modifier) {
            warn(s.loc, "multiple modifiers in sender");
            g.modifier = s.modifier;
        }
        applyPending(pending, g.params);
        addSurface(g, s);
    }
    if (g.surfaces.empty()) throw InputError(SourceLoc{file, 0}, "no sender surface");
    if (g.params.outSpec)
        warn(g.loc, "ignoring output file in sender ('" + *g.params.outSpec + "')");
    settleBasis(g, "missing sender sampling type", "undefined normal for sender sampling");
    const Vec3 u = cross(g.up, g.normal);
    if (!(length(u) > 0)) throw InputError(g.loc, "up vector coincides with sender normal");
    g.uAxis = normalize(u);
    g.vAxis = cross(g.normal, g.uAxis);
    if (g.params.sign == '-') g.uAxis = -g.uAxis;
    return g;
}

}  // namespace rp::flux
