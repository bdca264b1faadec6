// Emission plan: partitions, exact flux, partition CDF and photon emission (emitter.h).
#include "light/emitter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rp::light {

namespace {

// How a group of partitions draws directions.
enum class Mode : uint8_t {
    Hemisphere,  // Lambertian local emitter: cosine-weighted about the local normal
    FlatCone,    // flat spotlight: cos-weighted within the cone (exact sampler)
    CurvedCone,  // curved spotlight: joint rejection over (point, direction) in the group
    CubeCone,    // distant source from a cube face: cos-weighted within the source disk
    Table,       // modified source or port: -dp direction table
};

// What one source sends in unit direction `w` from point `p` with normal `n`: radiance x
// emission modifier x cos (zero behind the surface).
struct SourceValue {
    Color radiance;
    EmissionModifier mod;
    int32_t source = -1;
    Color operator()(const Vec3& w, const Vec3& p, const Vec3& n, bool distant) const {
        const double c = dot(w, n);
        if (!(c > 0)) return Color{};
        Color v = radiance * c;
        if (mod.eval) v *= mod.eval({distant ? w : -w, p, n, c, source});
        return v;
    }
};

struct Group {
    int32_t source = -1;  // -1: a port's exterior (-apE)
    int32_t port = -1, portPrim = -1;
    bool flipNormal = false;  // emit about minus the surface normal (forward ports)
    Mode mode = Mode::Hemisphere;
    Cone cone;  // spotlight cone or distant source disk
    // Hemisphere mode on a flat shape: its one normal's coneFrame, computed once.
    bool flatFrame = false;
    Vec3 frameU, frameV;
    Color radiance;
    Color weight;  // radiance scaled to the mean total flux (all modes but Table)
    bool distant = false;
    double maxDistance = 0;
    size_t first = 0, end = 0;  // partition range
};

}  // namespace

struct EmissionPlan::Impl {
    const ShapeSet* shapes = nullptr;
    SceneCube cube;
    std::vector<LightSource> sources;
    std::vector<Group> groups;
    std::vector<Partition> parts;
    std::vector<uint32_t> partGroup;
    std::vector<int32_t> partTable;
    std::vector<double> cdf;  // cumulative mean flux
    std::vector<DirectionTable> tables;
    Color total;
    std::vector<Color> sourceFlux;
    std::vector<size_t> sourceCount;
    Color exteriorFlux;
    std::vector<ExteriorPhoton> exteriorPhotons;

    // The constructor's phases, per kind of source: a local source's partitions; a
    // distant source through the scene cube's faces, or through the photon ports (each
    // side a port emits from).
    void planLocal(const LightSource& src, Group g, const SourceValue& value,
                   const EmissionOptions& options);
    void planCube(const LightSource& src, Group g, const SourceValue& value,
                  const EmissionOptions& options);
    void planPorts(const SceneGeometry& geometry, const LightSource& src, Group g,
                   const SourceValue& value, const EmissionOptions& options);
    void planPortSide(const SceneGeometry& geometry, const PhotonPort& port, int32_t portIndex,
                      const std::vector<Partition>& portParts, bool flip, Group g,
                      const SourceValue& value, const EmissionOptions& options);
    // -apE: each port side's exterior table (PortExterior), after the sources.
    void planExterior(const EmissionOptions& options);
    void planExteriorSide(const PhotonPort& port, int32_t portIndex,
                          const std::vector<Partition>& portParts, bool flip,
                          const PortExterior& exterior, uint64_t& rayIndex);

    void add(const Partition& p, uint32_t group, const Color& flux, int32_t table) {
        if (!(flux.average() > 0)) return;
        parts.push_back(p);
        partGroup.push_back(group);
        partTable.push_back(table);
        cdf.push_back((cdf.empty() ? 0.0 : cdf.back()) + flux.average());
        total += flux;
        const int32_t s = groups[group].source;
        (s >= 0 ? sourceFlux[size_t(s)] : exteriorFlux) += flux;
    }
    // Walker's alias table over all partitions (Vose's construction): slot i keeps
    // partition i with probability keep, else gives its alias, so a pick is one table
    // read. Why not a search of the cdf (still used within one group): even a guided,
    // branch-free search is a chain of dependent loads per photon (bench/README_profile.md).
    struct AliasEntry {
        double keep;     // probability of keeping the slot's own partition
        uint64_t alias;  // the partition taken otherwise
    };
    std::vector<AliasEntry> aliasTable;

    void buildAlias() {
        const size_t n = cdf.size();
        aliasTable.assign(n, AliasEntry{1.0, 0});
        std::vector<double> scaled(n);
        std::vector<size_t> small, large;
        for (size_t i = 0; i < n; ++i) {
            aliasTable[i].alias = i;
            scaled[i] = (cdf[i] - (i ? cdf[i - 1] : 0.0)) * double(n) / cdf.back();
            (scaled[i] < 1 ? small : large).push_back(i);
        }
        while (!small.empty() && !large.empty()) {
            const size_t lo = small.back(), hi = large.back();
            small.pop_back();
            aliasTable[lo] = AliasEntry{scaled[lo], hi};
            scaled[hi] -= 1 - scaled[lo];
            if (scaled[hi] < 1) {
                large.pop_back();
                small.push_back(hi);
            }
        }
        // What is left holds probability 1 up to rounding: keep = 1 (the default).
    }
    // The partition for uniform u in [0, 1): the slot floor(u n), kept or aliased by the
    // fraction u n - slot, itself uniform in [0, 1) and independent of the slot.
    size_t pickAny(double u) const {
        const double x = u * double(aliasTable.size());
        const size_t i = std::min(size_t(x), aliasTable.size() - 1);
        const AliasEntry& e = aliasTable[i];
        return x - double(i) < e.keep ? i : size_t(e.alias);
    }
    // Index of the first cdf entry in [first, end) above `target` (end if none), as
    // std::upper_bound.
    size_t upperBound(double target, size_t first, size_t end) const {
        if (end - first < 16) {
            // A few partitions (a lamp is often one): count the entries <= target, which
            // is upper_bound's answer on a sorted cdf, without its mispredicted branches.
            size_t count = 0;
            for (size_t j = first; j < end; ++j) count += cdf[j] <= target;
            return first + count;
        }
        return size_t(std::upper_bound(cdf.begin() + long(first), cdf.begin() + long(end), target) -
                      cdf.begin());
    }
    size_t pick(double u, size_t first, size_t end) const {
        double lo = first ? cdf[first - 1] : 0.0;
        double target = lo + u * (cdf[end - 1] - lo);
        return std::min(upperBound(target, first, end), end - 1);
    }
};

namespace {

// Integral over the axis angle of the projected solid angle of `cone` over a cone-family
// surface (the normal depends only on that angle), divided by 2 pi: the mean per unit
// area. 1024 midpoints: far finer than any -ds, so the result does not depend on it.
double meanConeSurfaceProjection(const ConeShape& c, const Cone& cone) {
    constexpr int kSteps = 1024;
    double sum = 0;
    for (int i = 0; i < kSteps; ++i) {
        double phi = 2 * kPi * (i + 0.5) / kSteps;
        Vec3 rho = c.e1 * std::cos(phi) + c.e2 * std::sin(phi);
        Vec3 n = normalize(rho - c.axis * c.slope);
        sum += projectedSolidAngle(cone, c.inward ? -n : n);
    }
    return sum / kSteps;
}

}  // namespace

EmissionPlan::EmissionPlan(const SceneGeometry& geometry, std::vector<LightSource> sources,
                           const EmissionOptions& options)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.shapes = &geometry.shapes();
    m.cube = geometry.sceneCube();
    m.sources = std::move(sources);
    m.sourceFlux.assign(m.sources.size(), Color{});
    m.sourceCount.assign(m.sources.size(), 0);
    if (!(options.partitionSize > 0)) throw InputError("-ds: partition size must be positive");
    for (size_t si = 0; si < m.sources.size(); ++si) {
        const LightSource& src = m.sources[si];
        SourceValue value{src.params.radiance, {}, int32_t(si)};
        if (src.modified()) {
            if (options.modifierFor) value.mod = options.modifierFor(src);
            if (!value.mod.eval)
                throw notSupportedYet(src.loc, "pattern-modified light source '" + src.name +
                                                   "' (emission modifier)");
        }
        Group g;
        g.source = int32_t(si);
        g.radiance = value.radiance;
        g.distant = src.distant();
        g.maxDistance = src.maxDistance;
        if (!src.distant())
            m.planLocal(src, g, value, options);
        else if (options.ports.empty())
            m.planCube(src, g, value, options);
        else
            m.planPorts(geometry, src, g, value, options);
    }
    // RADIANCE's error where no source reaches the ports (one set back behind glass,
    // whose source test the glass stops), also with -apE, whose exterior light alone
    // would then be emitted without the sun and sky.
    if (!(m.total.average() > 0)) throw InputError("zero flux from light sources");
    if (options.exterior && !options.ports.empty()) m.planExterior(options);
    // Every photon carries the mean total flux (same expression as emitPhoton's for
    // Table groups, so the same bits).
    for (Group& g : m.groups) g.weight = g.radiance * (m.total.average() / g.radiance.average());
    m.buildAlias();
}

void EmissionPlan::Impl::planLocal(const LightSource& src, Group g, const SourceValue& value,
                                   const EmissionOptions& options) {
    const size_t si = size_t(g.source);
    const Color& L = value.radiance;
    const std::vector<Partition> parts =
        partitionShape(*shapes, src.shape, src.shapeIndex, options.partitionSize * cube.size);
    for (const Partition& p : parts) sourceCount[si] += p.cells;
    const bool flat = src.shape == EmitterShape::Polygon || src.shape == EmitterShape::Ring;
    const bool spot = src.spotlight();
    if (spot) g.cone = {src.params.spotAim, std::cos(src.params.spotAngleDeg * kPi / 360)};
    g.first = this->parts.size();
    const uint32_t gi = uint32_t(groups.size());
    groups.push_back(g);
    if (src.modified()) {
        groups[gi].mode = Mode::Table;
        int32_t shared = -1;
        for (const Partition& p : parts) {
            EmissionPoint e = partitionCentre(*shapes, cube, p);
            int32_t t = shared;
            if (t < 0) {
                Cone ap = spot ? g.cone : Cone{e.normal, 0};
                tables.emplace_back(ap, options.samplesPerSr, [&](const Vec3& w) {
                    return value(w, e.point, e.normal, false);
                });
                t = int32_t(tables.size() - 1);
                if (flat && value.mod.directionalOnly) shared = t;
            }
            add(p, gi, tables[size_t(t)].integral() * p.area, t);
        }
    } else if (!spot) {
        groups[gi].mode = Mode::Hemisphere;
        if (flat && !parts.empty()) {
            // pointAt gives every point of a polygon or ring this same normal.
            const Vec3 n = partitionCentre(*shapes, cube, parts.front()).normal;
            groups[gi].flatFrame = true;
            coneFrame(n, groups[gi].frameU, groups[gi].frameV);
        }
        for (const Partition& p : parts) add(p, gi, L * (kPi * p.area), -1);
    } else if (flat) {
        groups[gi].mode = Mode::FlatCone;
        Vec3 n = partitionCentre(*shapes, cube, parts.front()).normal;
        double proj = projectedSolidAngle(g.cone, n);
        for (const Partition& p : parts) add(p, gi, L * (proj * p.area), -1);
    } else {
        // Exact total, spread over partitions by area: the joint rejection in emitPhoton
        // needs partitions chosen by area within the group.
        groups[gi].mode = Mode::CurvedCone;
        const double meanProj =
            src.shape == EmitterShape::Sphere  // projected area pi r^2 any way
                ? 0.25 * g.cone.solidAngle()
                : meanConeSurfaceProjection(shapes->cones[size_t(src.shapeIndex)], g.cone);
        for (const Partition& p : parts) add(p, gi, L * (meanProj * p.area), -1);
    }
    groups[gi].end = this->parts.size();
}

void EmissionPlan::Impl::planCube(const LightSource& src, Group g, const SourceValue& value,
                                  const EmissionOptions& options) {
    // Scene cube faces: the flux entering a face from the source disk is L * A * integral
    // over the disk of max(0, w . n_out); every ray entering the cube crosses exactly one
    // face, so the faces together deliver exactly the flux the source sends through it.
    const DistantSource& d = shapes->sources[size_t(src.shapeIndex)];
    g.cone = {d.dir, d.cosHalfAngle};
    const std::vector<Partition> faces = partitionCube(options.partitionSize);
    for (const Partition& p : faces) sourceCount[size_t(g.source)] += p.cells;
    g.first = parts.size();
    const uint32_t gi = uint32_t(groups.size());
    g.mode = src.modified() ? Mode::Table : Mode::CubeCone;
    groups.push_back(g);
    for (Partition p : faces) {
        p.area = cube.size * cube.size;
        EmissionPoint e = partitionCentre(*shapes, cube, p);
        if (src.modified()) {
            tables.emplace_back(g.cone, options.samplesPerSr,
                                [&](const Vec3& w) { return value(w, e.point, e.normal, true); });
            int32_t t = int32_t(tables.size() - 1);
            add(p, gi, tables[size_t(t)].integral() * p.area, t);
        } else {
            add(p, gi, value.radiance * (projectedSolidAngle(g.cone, e.normal) * p.area), -1);
        }
    }
    groups[gi].end = parts.size();
}

void EmissionPlan::Impl::planPorts(const SceneGeometry& geometry, const LightSource& src, Group g,
                                   const SourceValue& value, const EmissionOptions& options) {
    const DistantSource& d = shapes->sources[size_t(src.shapeIndex)];
    g.cone = {d.dir, d.cosHalfAngle};
    for (size_t pi = 0; pi < options.ports.size(); ++pi) {
        const PhotonPort& port = options.ports[pi];
        const std::vector<Partition> portParts =
            partitionShape(*shapes, port.shape, port.shapeIndex, options.partitionSize * cube.size);
        // Port normals point inside: photons enter along them when emitted about the
        // outward (flipped) normal.
        if (port.direction != PortDirection::Backward)
            planPortSide(geometry, port, int32_t(pi), portParts, true, g, value, options);
        if (port.direction != PortDirection::Forward)
            planPortSide(geometry, port, int32_t(pi), portParts, false, g, value, options);
    }
}

void EmissionPlan::Impl::planPortSide(const SceneGeometry& geometry, const PhotonPort& port,
                                      int32_t portIndex, const std::vector<Partition>& portParts,
                                      bool flip, Group g, const SourceValue& value,
                                      const EmissionOptions& options) {
    const bool flat = port.shape == EmitterShape::Polygon || port.shape == EmitterShape::Ring;
    for (const Partition& p : portParts) sourceCount[size_t(g.source)] += p.cells;
    g.port = portIndex;
    g.portPrim = port.prim;
    g.flipNormal = flip;
    g.mode = Mode::Table;
    g.first = parts.size();
    const uint32_t gi = uint32_t(groups.size());
    groups.push_back(g);
    // One table for a flat port under a direction-only modifier, each partition's own
    // where the source is partly hidden from it (or where the modifier depends on the
    // point). The partitions' tables are independent: built in parallel, then added in
    // partition order (the same plan for any number of threads).
    int32_t base = -1;
    if (flat && (!value.mod.eval || value.mod.directionalOnly) && !portParts.empty()) {
        EmissionPoint e = partitionCentre(*shapes, cube, portParts.front());
        Vec3 n = flip ? -e.normal : e.normal;
        tables.emplace_back(g.cone, options.samplesPerSr,
                            [&](const Vec3& w) { return value(w, e.point, n, true); });
        base = int32_t(tables.size() - 1);
    }
    std::vector<std::optional<DirectionTable>> own(portParts.size());
    tbb::parallel_for(size_t(0), portParts.size(), [&](size_t k) {
        EmissionPoint e = partitionCentre(*shapes, cube, portParts[k]);
        Vec3 n = flip ? -e.normal : e.normal;
        Vec3 from = e.point + n * e.offset;
        auto visible = [&](const Vec3& w) { return !geometry.occluded(from, w, HUGE_VAL); };
        if (base >= 0) {
            bool changed = false;
            DirectionTable seen = tables[size_t(base)].filtered(visible, changed);
            if (changed) own[k] = std::move(seen);
        } else {
            own[k].emplace(g.cone, options.samplesPerSr, [&](const Vec3& w) {
                return visible(w) ? value(w, e.point, n, true) : Color{};
            });
        }
    });
    for (size_t k = 0; k < portParts.size(); ++k) {
        int32_t t = base;
        if (own[k]) {
            tables.push_back(std::move(*own[k]));
            t = int32_t(tables.size() - 1);
        }
        add(portParts[k], gi, tables[size_t(t)].integral() * portParts[k].area, t);
    }
    groups[gi].end = parts.size();
}

void EmissionPlan::Impl::planExterior(const EmissionOptions& options) {
    uint64_t rayIndex = 0;
    const PortExterior& ex = options.exterior;
    for (size_t pi = 0; pi < options.ports.size(); ++pi) {
        const PhotonPort& port = options.ports[pi];
        const std::vector<Partition> portParts =
            partitionShape(*shapes, port.shape, port.shapeIndex, options.partitionSize * cube.size);
        if (port.direction != PortDirection::Backward)
            planExteriorSide(port, int32_t(pi), portParts, true, ex, rayIndex);
        if (port.direction != PortDirection::Forward)
            planExteriorSide(port, int32_t(pi), portParts, false, ex, rayIndex);
    }
}

void EmissionPlan::Impl::planExteriorSide(const PhotonPort& port, int32_t portIndex,
                                          const std::vector<Partition>& portParts, bool flip,
                                          const PortExterior& exterior, uint64_t& rayIndex) {
    if (portParts.empty()) return;
    Group g;
    g.port = portIndex;
    g.portPrim = port.prim;
    g.flipNormal = flip;
    g.mode = Mode::Table;
    g.distant = true;  // table directions point outside, photons travel against them
    g.radiance = Color{1, 1, 1};
    g.first = parts.size();
    const uint32_t gi = uint32_t(groups.size());
    groups.push_back(g);
    // One table per port side: the outside seen from `positions` points spread over the
    // port (partitions by area, then uniform within), the same points for every cell.
    double area = 0;
    for (const Partition& p : portParts) area += p.area;
    std::vector<EmissionPoint> points;
    Rng rng(0, RngDomain::Emission, uint64_t(portIndex) * 2 + (flip ? 1 : 0));
    for (int k = 0; k < exterior.positions; ++k) {
        double u = (k + rng.uniform()) / exterior.positions * area;
        size_t j = 0;
        while (j + 1 < portParts.size() && (u -= portParts[j].area) > 0) ++j;
        points.push_back(samplePartition(*shapes, cube, portParts[j], rng));
    }
    // How far beyond the port a surface facing back through it still counts as the
    // room's wall around the opening: a tenth of the port's size.
    const double setBack = 0.1 * std::sqrt(area);
    const Vec3 n0 = partitionCentre(*shapes, cube, portParts.front()).normal;
    const Vec3 axis = flip ? -n0 : n0;
    // Each ray that meets a surface leaves a photon there, standing for the area its
    // direction cell covers at that distance (cell solid angle t^2 / cos, shared among
    // the `positions` rays of the cell): the rays tile what the port sees outside.
    const size_t firstPhoton = exteriorPhotons.size();
    tables.emplace_back(
        DirectionTable::Averaged{}, Cone{axis, 0}, exterior.samplesPerSr, exterior.positions,
        [&](const Vec3& w, int k) {
            const EmissionPoint& e = points[size_t(k)];
            const Vec3 n = flip ? -e.normal : e.normal;
            const double c = dot(w, n);
            if (!(c > 0)) return Color{};
            const ExteriorView v = exterior.view(e.point + n * e.offset, w, rayIndex++);
            if (!v.surface) return Color{};
            // A port set back from the opening (users offset ports to keep them off the
            // glass) sees the room's own wall around the opening past its edges, facing
            // back through the port just beyond it: that is light of the room, not of
            // the outside (counted, a point beside a window 1 cm set back read 9-15 %
            // high). A facade across the street faces the port too, but far beyond it.
            if (dot(v.normal, n) < -0.5 && dot(v.point - e.point, n) < setBack) return Color{};
            const double cosSurface = std::fmax(std::fabs(dot(w, v.normal)), 1e-2);
            const double area = v.distance * v.distance / cosSurface / exterior.positions;
            exteriorPhotons.push_back({v.point, v.normal, v.ambient * area});
            return v.radiance * c;
        });
    const double omega = tables.back().cellSolidAngle();
    for (size_t i = firstPhoton; i < exteriorPhotons.size(); ++i) exteriorPhotons[i].flux *= omega;
    const int32_t t = int32_t(tables.size() - 1);
    for (const Partition& p : portParts) add(p, gi, tables[size_t(t)].integral() * p.area, t);
    groups[gi].end = parts.size();
}

EmissionPlan::~EmissionPlan() = default;
EmissionPlan::EmissionPlan(EmissionPlan&&) noexcept = default;
EmissionPlan& EmissionPlan::operator=(EmissionPlan&&) noexcept = default;

const std::vector<LightSource>& EmissionPlan::sources() const { return impl_->sources; }
Color EmissionPlan::totalFlux() const { return impl_->total; }
double EmissionPlan::totalFluxW() const { return impl_->total.average(); }
Color EmissionPlan::sourceFlux(size_t s) const { return impl_->sourceFlux.at(s); }
Color EmissionPlan::exteriorFlux() const { return impl_->exteriorFlux; }
const std::vector<ExteriorPhoton>& EmissionPlan::exteriorPhotons() const {
    return impl_->exteriorPhotons;
}
size_t EmissionPlan::partitionCount(size_t s) const { return impl_->sourceCount.at(s); }
size_t EmissionPlan::partitionCount() const {
    size_t n = 0;
    for (size_t c : impl_->sourceCount) n += c;
    return n;
}

EmittedPhoton EmissionPlan::emitPhoton(Rng& rng) const {
    const Impl& m = *impl_;
    size_t idx = m.pickAny(rng.uniform());
    const Group& g = m.groups[m.partGroup[idx]];
    EmissionPoint e = samplePartition(*m.shapes, m.cube, m.parts[idx], rng);
    Vec3 dir;
    Color colour = g.radiance;
    switch (g.mode) {
        case Mode::Hemisphere:
            dir = g.flatFrame ? sampleCosineHemisphere(e.normal, g.frameU, g.frameV, rng)
                              : sampleProjectedCone(Cone{e.normal, 0}, e.normal, rng);
            break;
        case Mode::FlatCone:
            dir = sampleProjectedCone(g.cone, e.normal, rng);
            break;
        case Mode::CurvedCone:
            // Point uniform by area over the whole group, direction uniform in the cone,
            // accepted with probability max(0, w.n): exactly L cos dA dw within the cone.
            for (int tries = 0;; ++tries) {
                dir = sampleUniformCone(g.cone, rng);
                if (rng.uniform() < dot(dir, e.normal) || tries > 1000000) break;
                idx = m.pick(rng.uniform(), g.first, g.end);
                e = samplePartition(*m.shapes, m.cube, m.parts[idx], rng);
            }
            break;
        case Mode::CubeCone:
            dir = -sampleProjectedCone(g.cone, e.normal, rng);
            break;
        case Mode::Table: {
            Vec3 n = g.flipNormal ? -e.normal : e.normal;
            const DirectionTable& t = m.tables[size_t(m.partTable[idx])];
            DirectionTable::Sample s = t.sample(rng, [&](const Vec3& w) { return dot(w, n) > 0; });
            dir = g.distant ? -s.dir : s.dir;
            colour = s.value;
            break;
        }
    }
    EmittedPhoton ph;
    ph.source = g.source;
    ph.exterior = g.source < 0;
    ph.weight = g.mode == Mode::Table ? colour * (m.total.average() / colour.average()) : g.weight;
    Hit h;
    h.point = e.point;
    h.normal = e.normal;
    h.offset = e.offset;
    if (g.port >= 0) {
        // Start just behind the port, back along the ray (as pmapsrc.c does), so that
        // the photon crosses the port at the sampled point and is scattered by it.
        double cosN = std::fmax(std::fabs(dot(dir, e.normal)), 1e-3);
        ph.ray = Ray{e.point - dir * (e.offset / cosN), dir, HUGE_VAL};
        ph.port = g.port;
        ph.portPrim = g.portPrim;
    } else if (g.distant) {
        ph.ray = Ray{e.point, dir, HUGE_VAL};
    } else {
        ph.ray = spawnRay(h, dir, g.maxDistance > 0 ? g.maxDistance : HUGE_VAL);
    }
    return ph;
}

}  // namespace rp::light
