// Photon tracing for mkpmap (RADIANCE pmap.c tracePhoton, pmapmat.c photonScatter and
// addPhotons), as a loop over path segments instead of RADIANCE's recursion.
#include "pmap/trace.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "light/light_sources.h"
#include "material/clip_set.h"
#include "util/error.h"
#include "util/henyey_greenstein.h"

namespace rp::pmap {

namespace {

using material::ScatterKind;

int8_t packNormal(double v) { return static_cast<int8_t>(127.0 * v); }

// A deposit's record; `n` is the surface normal facing the photon, or for volume photons
// the direction it travelled in (RADIANCE newPhoton).
RawPhoton rawPhoton(const Vec3& p, const Vec3& n, const Color& flux, bool caustic) {
    RawPhoton rp;
    rp.pos[0] = float(p.x);
    rp.pos[1] = float(p.y);
    rp.pos[2] = float(p.z);
    rp.norm[0] = packNormal(n.x);
    rp.norm[1] = packNormal(n.y);
    rp.norm[2] = packNormal(n.z);
    rp.caustic = caustic ? 1 : 0;
    rp.flux[0] = float(flux.r);
    rp.flux[1] = float(flux.g);
    rp.flux[2] = float(flux.b);
    rp.u = 0;
    return rp;
}

}  // namespace

PhotonTracer::PhotonTracer(const Scene& scene, const SceneGeometry& geometry,
                           const light::EmissionPlan& plan, TraceSettings settings,
                           const material::SurfaceChains& chains,
                           const material::MaterialCalc* materialCalc)
    : scene_(scene),
      geometry_(geometry),
      cube_(geometry.sceneCube()),
      chains_(chains),
      materials_(chains.materials()),
      materialCalc_(materialCalc),
      plan_(plan),
      settings_(std::move(settings)) {
    const auto& prims = scene.prims;
    surfaces_.resize(prims.size());
    roles_.assign(prims.size(), 0);
    std::unordered_set<std::string> include(settings_.include.begin(), settings_.include.end());
    std::unordered_set<std::string> exclude(settings_.exclude.begin(), settings_.exclude.end());
    std::unordered_set<std::string> sensors(settings_.sensors.begin(), settings_.sensors.end());

    // Sensors: every modifier of that name must be antimatter (pmapmat.c getPhotonSensors).
    bool sensorFound = false;
    for (size_t i = 0; i < prims.size(); ++i) {
        const Primitive& p = prims[i];
        if (materials_.usable(int32_t(i)) &&
            material::needsPreparation(materialCalc_, int32_t(i), *materials_[int32_t(i)].params))
            roles_[i] |= kPrepare;
        if (!isModifier(p.type) || !sensors.count(p.name)) continue;
        if (!materials_.usable(int32_t(i)) || !materials_[int32_t(i)].antimatter)
            throw InputError(p.loc, "photon sensor modifier " + p.name + " is not antimatter");
        roles_[i] |= kSensor;
        sensorFound = true;
    }
    if (!sensors.empty() && !sensorFound) throw InputError("no photon sensors found");

    for (size_t i = 0; i < prims.size(); ++i) {
        const Primitive& surf = prims[i];
        if (!isSurface(surf.type) || surf.modifier == kVoid) continue;
        SurfaceModifier& info = surfaces_[size_t(surf.modifier)];
        if (info.resolved) continue;
        info.resolved = true;
        const Primitive& mod = prims[size_t(surf.modifier)];
        info.storeAllowed =
            include.empty() ? !exclude.count(mod.name) : include.count(mod.name) > 0;
        info.plain = chains_.isPlain(surf.modifier);
        if (info.plain) {
            info.material = chains_.plainMaterial(surf.modifier);
            if (info.material != kVoid) scatterer(info.material);  // errors now, at its line
            continue;
        }
        chains_.checkChain(surf.modifier);
        info.material = chainMaterial(scene, surf.modifier);  // for the port test
    }
    for (const light::LightSource& s : plan_.sources()) sourceMaxDistance_.push_back(s.maxDistance);
    findSourceMedia();
}

void PhotonTracer::findSourceMedia() {
    const auto& sources = plan_.sources();
    sourceMedium_.assign(sources.size(), settings_.medium);
    sourceMists_.assign(sources.size(), material::MistSet{});
    if (!material::sceneHasMist(scene_)) return;
    const ShapeSet& shapes = geometry_.shapes();
    Rng rng(0, RngDomain::Sampling, 0);  // mixtures along the probe; fixed, as the map is
    for (size_t s = 0; s < sources.size(); ++s) {
        const light::LightSource& src = sources[s];
        const size_t i = size_t(src.shapeIndex);
        Vec3 centre;
        switch (src.shape) {
            case light::EmitterShape::Sphere:
                centre = shapes.spheres[i].center;
                break;
            case light::EmitterShape::Ring:
                centre = shapes.rings[i].centre;
                break;
            case light::EmitterShape::Polygon:
                centre = shapes.polygons[i].vertexMean;
                break;
            case light::EmitterShape::Cone:
                centre = shapes.cones[i].p0 + shapes.cones[i].axis * (0.5 * shapes.cones[i].length);
                break;
            case light::EmitterShape::Distant:
                continue;  // from outside the scene
        }
        sourceMedium_[s] =
            material::mediumWithin(material::enclosingMists(geometry_, chains_, centre, rng),
                                   settings_.medium, materials_, sourceMists_[s]);
    }
}

const material::MaterialRecord& PhotonTracer::scatterer(int32_t m) const {
    const material::MaterialRecord& r = materials_.at(m);
    // RADIANCE's photon tracer has no prism1/prism2 scattering (pmapmat.c leaves them to
    // its default, an error); we say so at the material's line.
    if (!r.scattersPhotons) {
        const Primitive& p = scene_.prims[size_t(m)];
        throw notSupportedYet(p.loc,
                              std::string(primTypeName(p.type)) + " material in photon maps");
    }
    return r;
}

int32_t PhotonTracer::resolveChain(int32_t modifier, const Hit& hit, const Vec3& dir,
                                   material::HitEvaluators& evals, Rng& rng, Color& pattern,
                                   Vec3& perturbation) const {
    const auto at = material::PatternPoint::atHit(dir, hit);
    material::ChainResult c = evals.chains().resolve(modifier, at, rng);
    if (c.count <= 0) return kVoid;
    int pick = 0;
    if (c.count > 1) {
        double u = rng.uniform();
        while (pick + 1 < c.count && (u -= c.layers[size_t(pick)].weight) >= 0) ++pick;
    }
    const material::ShadingLayer& l = c.layers[size_t(pick)];
    pattern = l.pattern;
    perturbation = l.perturbation;
    return l.material;
}

bool PhotonTracer::inRegions(const Vec3& p) const {
    if (settings_.rois.empty()) return true;
    for (const RegionOfInterest& r : settings_.rois)
        if (r.contains(p)) return true;
    return false;
}

void PhotonTracer::deposit(const Hit& hit, bool front, const Color& flux, bool indirect,
                           bool caustic, const std::array<double, kNumPhotonMapTypes>& prob,
                           Rng& storeRng, PhotonBins& out) const {
    if (!inRegions(hit.point)) return;
    // One storage draw per eligible deposit, in the fixed order below (deterministic);
    // the record is filled only when a draw keeps it: most deposits of a map with a
    // small storage probability are dropped. u < 0: not kept.
    auto draw = [&](PhotonMapType t) -> float {
        const size_t k = size_t(t);
        if (!settings_.maps[k]) return -1;
        const double u = storeRng.uniform();
        return u < prob[k] ? float(u) : -1.0f;
    };
    // pmapmat.c addPhotons: direct at the first hit, global (and caustic after specular
    // paths) afterwards.
    float u[3];
    PhotonMapType types[3] = {PhotonMapType::Global, PhotonMapType::PreComp,
                              PhotonMapType::Caustic};
    if (!indirect) {
        types[0] = PhotonMapType::Direct;
        u[0] = draw(PhotonMapType::Direct);
        u[1] = u[2] = -1;
    } else {
        u[0] = draw(PhotonMapType::Global);
        u[1] = draw(PhotonMapType::PreComp);  // -app: global photons, precomputed later
        u[2] = caustic ? draw(PhotonMapType::Caustic) : -1;
    }
    if (u[0] < 0 && u[1] < 0 && u[2] < 0) return;
    const Vec3 n = front ? hit.normal : -hit.normal;  // facing the incoming photon
    RawPhoton rp = rawPhoton(hit.point, n, flux, indirect && caustic);
    for (int i = 0; i < 3; ++i) {
        if (u[i] < 0) continue;
        rp.u = u[i];
        out.maps[size_t(types[i])].push_back(rp);
    }
}

// One photon's way through the scene: the state trace()'s phases read and change.
struct PhotonTracer::PhotonPath {
    PhotonPath(const PhotonTracer& t, Workspace& ws, uint64_t seed, uint64_t index,
               const StoreProbabilities& p, PhotonBins& o)
        : e(t.plan_.emitPhoton(seed, index)),
          rng(seed, RngDomain::Scattering, index),
          storeRng(seed, RngDomain::Sampling, index),
          ray(e.ray),
          flux(e.weight),
          sp(ws.sp_),
          scratch(ws.scratch_),
          evals(ws.evals_),
          prob(p),
          out(o) {
        // Path length limit: -ld and a local glow's radius (pmapsrc.c: the photon's rmax).
        pathLimit = t.settings_.maxDistance > 0 ? t.settings_.maxDistance : HUGE_VAL;
        if (e.source >= 0 && t.sourceMaxDistance_[size_t(e.source)] > 0)
            pathLimit = std::fmin(pathLimit, t.sourceMaxDistance_[size_t(e.source)]);
        // What encloses its source (RADIANCE's photons start in the global medium,
        // whatever encloses them); photons from ports come from outside.
        const bool local = e.source >= 0 && e.port < 0;
        medium = local ? t.sourceMedium_[size_t(e.source)] : t.settings_.medium;
        if (local) mists = t.sourceMists_[size_t(e.source)];
        // What a photon meets first is direct light, stored in direct maps only
        // (pmapmat.c addPhotons): the renderer's direct calculation counts it, and a
        // global map holding it would count it again at every final-gather hit (issue 42:
        // a ceiling point read 41.0 against 24.0). A photon from a port starts just outside
        // it and is scattered by the port's own material (pmapsrc.c emitPhoton): past an
        // antimatter or void port its first hit is still direct, past glass, trans or a
        // BSDF it is indirect. Deliberately unlike RADIANCE: the first hits of a sky or
        // ground glow are indirect, since no direct calculation holds their light
        // (LightSource::ambientOnly). RADIANCE stores them in direct maps only and loses
        // that light at final-gather hits (ceiling points under a sky through an
        // antimatter port read 0.53 for 1.21 classic).
        // Light of the surfaces outside a port (-apE) is ambient light as well.
        firstHitIndirect =
            e.exterior || (e.source >= 0 && t.plan_.sources()[size_t(e.source)].ambientOnly());
        // A spotlight's focus (the length of its direction vector) lies that far behind
        // it: classic direct light falls off as (d / (d + flen))^2 (RADIANCE source.c
        // srcray), and photons follow it where RADIANCE's do not (manual 9).
        if (local) {
            const light::LightSource& src = t.plan_.sources()[size_t(e.source)];
            if (src.spotlight() && src.shape != light::EmitterShape::Distant)
                spotFocus = src.params.spotFocalLength;
        }
    }

    // RADIANCE compat (pmap.h PMAP_CAUSTICRAY): a photon is caustic when its last scatter
    // was specular, so D S+ D paths count too, not only L S+ D. The renderer adds the
    // caustic map at primary rays and its final gather does not follow specular
    // transport, so this is what keeps the two maps from missing or double counting light
    // reflected by mirrors and glass after a diffuse bounce (cornell: RADIANCE's caustic
    // map is tinted by the walls). It also needs ~3x fewer emitted photons.
    bool caustic() const { return scatters > 0 && lastSpecular; }
    bool indirect() const { return scatters > 0 || firstHitIndirect; }
    // Where the photon's light arrives (a deposit, a diffuse or volume scatter), its flux
    // takes the spotlight focus's fall-off over the path travelled, once; mirrors and
    // glass before it pass the light on, as virtual sources and shadow rays do.
    void arrive() {
        if (spotFocus <= 0) return;
        const double f = travelled / (travelled + spotFocus);
        flux *= f * f;
        spotFocus = 0;
    }
    // On through `hit` unchanged (PMAP_XFER): not a bounce.
    void passOn(const Hit& hit) {
        ray = spawnRay(hit, ray.dir);
        ++passes;
    }

    light::EmittedPhoton e;
    Rng rng, storeRng;
    double pathLimit = HUGE_VAL;
    // The photon's ray and flux, where emission put them (copies stalled on reading back
    // what emitPhoton had just written).
    Ray& ray;
    Color& flux;
    material::Medium medium;
    material::MistSet mists;
    bool firstHitIndirect = false;
    double spotFocus = 0;  // pending focal length of a spotlight's photon
    long scatters = 0, passes = 0;
    bool lastSpecular = false;
    bool firstSegment = true;
    double travelled = 0;
    material::ClipSet clip;
    // The thread's (Workspace), set at each hit (setSurfaceHit, pattern, normal, and
    // prepareHit for what a material's functions give, cleared again after the scatter);
    // its other fields keep their defaults.
    material::SurfacePoint& sp;
    material::HitScratch& scratch;
    material::HitEvaluators& evals;
    const StoreProbabilities& prob;
    PhotonBins& out;
};

PhotonTracer::MediumStep PhotonTracer::travelMedium(PhotonPath& path, const Hit* hit,
                                                    const material::Medium& m) const {
    Ray& ray = path.ray;
    Color& flux = path.flux;
    // The free path is drawn from the mean extinction, as RADIANCE does; the flux is
    // weighted per channel by the ratio of the true probabilities to the drawn one (1 in
    // a grey medium), which keeps coloured media unbiased where RADIANCE only renormalises
    // the colour.
    const double mean = m.extinction.average();
    const double t = hit ? hit->t : HUGE_VAL;
    const double d = -std::log(1 - path.rng.uniform()) / mean;
    if (!(d < t)) {
        if (!hit) return MediumStep::Lost;
        for (int k = 0; k < 3; ++k) flux[k] *= std::exp((mean - m.extinction[k]) * t);
        return MediumStep::Reached;
    }
    const Vec3 p = ray.origin + ray.dir * d;
    // Past the path limit (-ld), or scattered outside the scene's cube: leaked.
    if (!(d <= ray.tmax)) return MediumStep::Lost;
    for (int k = 0; k < 3; ++k)
        if (!(p[k] >= cube_.origin[k] && p[k] <= cube_.origin[k] + cube_.size))
            return MediumStep::Lost;
    path.travelled += d;
    for (int k = 0; k < 3; ++k)
        flux[k] *= m.extinction[k] / mean * std::exp((mean - m.extinction[k]) * d);
    path.arrive();
    // pmap.c: every collision in a scattering medium is stored, the first one too: the
    // volume map carries the direct in-scattering as well (render/medium.cpp).
    const double albedo = m.albedo.average();
    if (albedo > 1e-6 && settings_.maps[size_t(PhotonMapType::Volume)] && inRegions(p)) {
        const double u = path.storeRng.uniform();
        if (u < path.prob[size_t(PhotonMapType::Volume)]) {
            RawPhoton rp = rawPhoton(p, ray.dir, flux, false);
            rp.u = float(u);
            path.out.maps[size_t(PhotonMapType::Volume)].push_back(rp);
        }
    }
    if (!(path.rng.uniform() < albedo)) return MediumStep::Lost;  // absorbed
    flux *= m.albedo / albedo;
    ray = Ray{p, sampleHenyeyGreenstein(ray.dir, m.eccentricity, path.rng)};
    return MediumStep::Scattered;
}

PhotonTracer::MediumStep PhotonTracer::crossMist(PhotonPath& path, const material::MistParams& mist,
                                                 int32_t matIndex, const Hit& hit,
                                                 const Color& pattern) const {
    material::Medium& medium = path.medium;
    material::MistSet& mists = path.mists;
    const material::MediumChange crossing = material::mistCrossing(mist, hit.front, pattern);
    if (hit.front) {
        mists.enter(matIndex);
    } else if (!mists.leave(matIndex)) {
        // Leaving a mist it never entered, the photon was emitted inside it (a lamp in the
        // fog), which RADIANCE's photons ignore. The mist's own extinction, independent of
        // the medium's already travelled, may stop it on the way here.
        material::MediumChange enter = crossing;
        enter.kind = material::MediumChange::Kind::EnterMist;
        const material::Medium inside =
            material::changeMedium(medium, enter, settings_.medium, &mist);
        const material::Medium extra{inside.extinction - medium.extinction, inside.albedo,
                                     inside.eccentricity};
        medium = inside;
        if (extra.active()) {
            path.travelled -= hit.t;
            const MediumStep step = travelMedium(path, &hit, extra);
            if (step != MediumStep::Reached) {
                if (step == MediumStep::Scattered) mists.enter(matIndex);
                return step;
            }
            path.travelled += hit.t;
        }
    }
    medium = material::changeMedium(medium, crossing, settings_.medium, &mist);
    path.ray = spawnRay(hit, path.ray.dir);
    return MediumStep::Reached;
}

void PhotonTracer::trace(Workspace& workspace, uint64_t seed, uint64_t index,
                         const StoreProbabilities& prob, PhotonBins& out) const {
    PhotonPath path(*this, workspace, seed, index, prob, out);
    while (advance(path)) {
    }
}

bool PhotonTracer::advance(PhotonPath& p) const {
    if (p.scatters > settings_.maxBounce || p.passes > 4 * settings_.maxBounce + 1000) {
        ++p.out.runaways;  // manual 4.3: terminated, warned once at the end
        return false;
    }
    p.ray.tmax = p.pathLimit - p.travelled;
    if (!(p.ray.tmax > 0)) return false;
    std::optional<Hit> hit = geometry_.closestHit(p.ray);
    if (p.medium.active()) {
        MediumStep step = travelMedium(p, hit ? &*hit : nullptr, p.medium);
        if (step == MediumStep::Lost) return false;
        if (step == MediumStep::Scattered) {
            // Surface photons after this are indirect (global), never caustic.
            ++p.scatters;
            p.lastSpecular = false;
            p.firstSegment = false;
            return true;
        }
    }
    if (!hit) return false;
    p.travelled += hit->t;
    if (rejectedAtPort(p, *hit)) return false;
    return atSurface(p, *hit);
}

bool PhotonTracer::rejectedAtPort(PhotonPath& p, const Hit& hit) const {
    const bool first = p.firstSegment;
    p.firstSegment = false;
    // pmap.c port rejection: a photon emitted from a port's partition that misses the port
    // geometry is terminated (the partition overestimates its area).
    if (!first || p.e.port < 0 || hit.prim == p.e.portPrim) return false;
    const int32_t pm = scene_.prims[size_t(p.e.portPrim)].modifier;
    const int32_t hm = hit.modifier;
    const int32_t portMat = pm == kVoid ? kVoid : surfaces_[size_t(pm)].material;
    const int32_t hitMat = hm == kVoid ? kVoid : surfaces_[size_t(hm)].material;
    return portMat != hitMat;
}

bool PhotonTracer::atSurface(PhotonPath& p, const Hit& hit) const {
    const int32_t modIndex = hit.modifier;
    const SurfaceModifier* surf = modIndex == kVoid ? nullptr : &surfaces_[size_t(modIndex)];
    if (!surf || surf->material == kVoid || p.clip.contains(modIndex)) {
        p.passOn(hit);  // void modifier or clipped by antimatter
        return true;
    }
    // The chain at this hit: patterns colour the albedo, textures tilt the scattering
    // normal (the stored photon keeps the surface's own), a mixture picks a material.
    ChainHit at;
    at.material = surf->plain ? surf->material
                              : resolveChain(modIndex, hit, p.ray.dir, p.evals, p.rng, at.pattern,
                                             at.perturbation);
    at.perturbation += hit.perturbation;  // a mesh's vertex normals (RADIANCE o_mesh.c)
    if (at.material == kVoid) {
        p.passOn(hit);
        return true;
    }
    // Plain chains' materials were checked in the constructor.
    const material::MaterialRecord& mi =
        surf->plain ? materials_[at.material] : scatterer(at.material);
    if (mi.antimatter) {
        // pmapmat.c clipPhotonScatter: a sensor stores photons entering it (front side)
        // and passes them on unscattered, like any antimatter.
        if (hit.front && (roles_[size_t(at.material)] & kSensor) && surf->storeAllowed) {
            p.arrive();
            deposit(hit, true, p.flux, p.indirect(), p.caustic(), p.prob, p.storeRng, p.out);
        }
        p.clip.cross(mi.clips, hit.front);
        p.passOn(hit);
        return true;
    }
    if (const material::MistParams* mist = material::mistOf(mi)) {
        // pmapmat.c mistPhotonScatter: passed on (not a bounce) into the medium it enters
        // or returns to.
        const MediumStep step = crossMist(p, *mist, at.material, hit, at.pattern);
        if (step == MediumStep::Lost) return false;
        if (step == MediumStep::Scattered) {
            ++p.scatters;
            p.lastSpecular = false;
        } else {
            ++p.passes;
        }
        return true;
    }
    if (mi.isLight) return false;  // "Light sources doan' reflect"; nothing stored
    if (!hit.front && !settings_.backVisible && mi.backAbsorbs) return false;
    return scatterAt(p, hit, at, mi, surf->storeAllowed);
}

bool PhotonTracer::scatterAt(PhotonPath& p, const Hit& hit, const ChainHit& at,
                             const material::MaterialRecord& mi, bool storeAllowed) const {
    material::SurfacePoint& sp = p.sp;
    const Vec3 facing = hit.front ? hit.normal : -hit.normal;
    material::setSurfaceHit(sp, p.ray.dir, facing, hit.front);
    sp.backVisible = settings_.backVisible;
    sp.pattern = at.pattern;
    if (lengthSquared(at.perturbation) > 0)  // RADIANCE raynormal, turned to the photon
        material::perturbSurface(sp, hit.normal, at.perturbation);
    const bool prepared = roles_[size_t(at.material)] & kPrepare;
    if (prepared)
        material::prepareHit(p.evals, at.material, *mi.params,
                             material::PatternPoint::atHit(p.ray.dir, hit), sp, p.scratch, p.rng);
    const material::PhotonScatter s = material::scatterPhoton(*mi.params, sp, p.rng);
    if (prepared) material::resetPreparedInputs(sp);
    if (s.store || !(s.kind == ScatterKind::PassThrough || material::isSpecular(s.kind)))
        p.arrive();
    if (s.store && storeAllowed)
        deposit(hit, hit.front, p.flux, p.indirect(), p.caustic(), p.prob, p.storeRng, p.out);
    if (s.kind == ScatterKind::Absorbed) return false;
    if (s.kind == ScatterKind::PassThrough) {
        p.passOn(hit);
        return true;
    }
    p.flux *= s.fluxFactor;
    ++p.scatters;
    p.lastSpecular = material::isSpecular(s.kind);
    p.medium = material::changeMedium(p.medium, material::MediumChange{s.mediumKind, s.extinction},
                                      settings_.medium);
    p.ray = spawnRay(hit, s.dir);
    if (s.originOffset != 0) p.ray.origin += hit.normal * double(s.originOffset);
    return true;
}

}  // namespace rp::pmap
