// Variable-resolution BSDF data ("tensor trees", LBNL/Shirley-Chiu basis) as RADIANCE's
// bsdf_t.c reads and uses them: 3-D isotropic (TensorTree3) and 4-D (TensorTree4) trees
// over the unit hypercube, incident coordinates first. A 4-D tree's coordinates are the
// Shirley-Chiu square positions of -in (dims 0, 1) and of out (dims 2, 3); a 3-D tree's
// are the incident radius, .5 - |in.xy| / 2 (only [0, .5) used), and the square position
// of out rotated so that -in lies along +X. Values are per-steradian BSDFs, constant on
// each leaf (no interpolation). Sampling tables are built per incident cell on first
// use and published lock-free.
#include "bsdf/tensor_tree.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <optional>

#include "bsdf/colour.h"

namespace rp::bsdf::detail {
namespace {

using namespace ttree;

// ---------------------------------------------------------------------------------
// The cumulative distribution over outgoing cells for one incident cell (RADIANCE's
// SDTreCDst): cells sorted along the Hilbert curve, each with the cumulative value
// (scaled to 2^32 - 1) of BSDF * projected solid angle before it.
struct CDist {
    struct Entry {
        uint32_t hilbert;  // first index of the cell's run on the 2^16 Hilbert grid
        uint32_t cuml;
    };
    double clim[2][2];                  // incident coordinates this table serves: [lo, hi) per dim
    double cTotal = 0;                  // directional-hemispherical value
    double minWidth = 1, maxWidth = 0;  // of the outgoing cells (square units)
    Side outSide = Side::ReflFront;     // side of the sampled directions
    std::vector<Entry> cells;           // plus a final entry with cuml = 2^32 - 1
    const CDist* next = nullptr;        // more tables sharing a cache slot

    bool serves(const double c[2], int nic) const {
        for (int i = 0; i < nic; ++i)
            if (c[i] < clim[i][0] || c[i] >= clim[i][1]) return false;
        return true;
    }
};

class TreeDistribution final : public Distribution {
public:
    TreeDistribution(Tree tree, Side side);
    // CIE-u and CIE-v trees colour the values; `minRgb` is the Lambertian colour already
    // taken out of the Y tree (its brightness), so that value() gives what is left.
    void setColour(Tree u, Tree v, const Color& minRgb) {
        u_ = std::move(u);
        v_ = std::move(v);
        minRgb_ = minRgb;
    }

    Color value(const Vec3& in, const Vec3& out) const override;
    void projectedSolidAngle(const Vec3& v1, const Vec3* v2, SizeQuery q,
                             double psa[2]) const override;
    double hemispherical(const Vec3& in) const override;
    bool sample(const Vec3& in, double x, double y, Vec3& out) const override;
    bool coloured() const override { return u_.has_value() && v_.has_value(); }

    const Tree& tree() const { return tree_; }

private:
    struct Cache {
        std::unique_ptr<std::atomic<const CDist*>[]> slots;
    };

    bool gridPosition(Vec3 in, Vec3 out, double pos[4]) const;
    const CDist* cdist(const Vec3& in) const;
    const CDist* findOrBuild(int mode, const double c[2]) const;
    std::unique_ptr<CDist> build(bool rev, const double c[2]) const;
    void publish(const Cache& cache, CDist* cd, size_t slot) const;
    size_t slotOf(const double c[2]) const;

    Tree tree_;
    std::optional<Tree> u_, v_;  // colour (CIE 1976 u', v'), where given
    Color minRgb_;
    Side side_;
    int nic_;         // incident coordinates: 1 (3-D) or 2
    double quantum_;  // incident coordinates are snapped to cell centres of this size
    int slotBits_;    // cache slots per incident coordinate: 2^slotBits_
    Cache cache_[2];  // [0] as stored, [1] reversed (transmission by reciprocity)
    mutable std::mutex buildMutex_;  // only taken to build a missing table
    mutable std::vector<std::unique_ptr<CDist>> built_;
};

TreeDistribution::TreeDistribution(Tree tree, Side side)
    : tree_(std::move(tree)), side_(side), nic_(tree_.ndim - 2) {
    const double leaf = tree_.smallestLeaf();
    quantum_ = std::min(1.0 / 256, leaf);  // RADIANCE shares one such value between files
    slotBits_ = std::min(static_cast<int>(std::lround(-std::log2(leaf))), 7);
    const size_t nslots = size_t(1) << (slotBits_ * nic_);
    const bool xmit = side == Side::XmitFront || side == Side::XmitBack;
    for (int m = 0; m < (xmit ? 2 : 1); ++m) {
        cache_[m].slots.reset(new std::atomic<const CDist*>[nslots]);
        for (size_t i = 0; i < nslots; ++i) cache_[m].slots[i].store(nullptr);
    }
}

// The tree coordinates for a pair (SDqueryTre), false where the pair is not this
// tree's kind of scattering. Transmission in the other direction swaps the pair.
bool TreeDistribution::gridPosition(Vec3 in, Vec3 out, double pos[4]) const {
    switch (side_) {
        case Side::ReflFront:
            if (out.z < 0 || in.z < 0) return false;
            break;
        case Side::ReflBack:
            if (out.z > 0 || in.z > 0) return false;
            break;
        case Side::XmitFront:
            if (out.z > 0) {
                if (in.z > 0) return false;
                std::swap(in, out);
            } else if (in.z < 0) {
                return false;
            }
            break;
        case Side::XmitBack:
            if (in.z > 0) {
                if (out.z > 0) return false;
                std::swap(in, out);
            } else if (out.z < 0) {
                return false;
            }
            break;
    }
    if (tree_.ndim == 3) {
        const Vec3 r = spinZ(out, -std::atan2(-in.y, -in.x));
        pos[0] = (.5 - kTiny) - .5 * std::sqrt(in.x * in.x + in.y * in.y);
        diskToSquare(r.x, r.y, pos + 1);
    } else {
        diskToSquare(-in.x, -in.y, pos);
        diskToSquare(out.x, out.y, pos + 2);
    }
    return true;
}

Color TreeDistribution::value(const Vec3& in, const Vec3& out) const {
    double pos[4], w;
    if (!gridPosition(in, out, pos)) return {};
    const double y = tree_.lookup(pos, w);
    if (!u_) return Color::grey(y);
    // The whole value's colour less the Lambertian colour (bsdf_t.c subtract_min_RGB
    // rewrites the u' v' trees to that effect).
    Color c = rgbOfYuv(y + minRgb_.brightness(), u_->lookup(pos, w), v_->lookup(pos, w)) - minRgb_;
    for (int i = 0; i < 3; ++i) c[i] = std::max(0.0, c[i]);
    return c;
}

void TreeDistribution::projectedSolidAngle(const Vec3& v1, const Vec3* v2, SizeQuery q,
                                           double psa[2]) const {
    double mine[2] = {0, 0};
    if (v2) {
        double pos[4], w;
        if (!gridPosition(v1, *v2, pos)) return;
        tree_.lookup(pos, w);
        mine[0] = mine[1] = kPi * w * w;
    } else if (const CDist* cd = cdist(v1)) {
        mine[0] = kPi * (cd->clim[0][1] - cd->clim[0][0]) * (cd->clim[1][1] - cd->clim[1][0]);
        mine[1] = kPi * cd->maxWidth * cd->maxWidth;
    }
    switch (q) {
        case SizeQuery::Max:
            if (mine[1] > psa[0]) psa[0] = mine[1];
            return;
        case SizeQuery::MinMax:
            if (mine[1] > psa[1]) psa[1] = mine[1];
            [[fallthrough]];
        case SizeQuery::Min:
            if (mine[0] > 0 && mine[0] < psa[0]) psa[0] = mine[0];
            return;
    }
}

double TreeDistribution::hemispherical(const Vec3& in) const {
    const CDist* cd = cdist(in);
    return cd ? cd->cTotal : 0;
}

// Incident coordinates snapped to the centre of a quantum-sized cell (SDgetTreCDist),
// so that directions on a cell boundary always get the same table; null where this tree
// has nothing for light from `in`.
const CDist* TreeDistribution::cdist(const Vec3& in) const {
    Side mode = side_;
    switch (side_) {
        case Side::ReflFront:
            if (in.z < 0) return nullptr;
            break;
        case Side::ReflBack:
            if (in.z > 0) return nullptr;
            break;
        case Side::XmitFront:
            if (in.z < 0) mode = Side::XmitBack;
            break;
        case Side::XmitBack:
            if (in.z > 0) mode = Side::XmitFront;
            break;
    }
    const bool rev = mode != side_;
    double c[2] = {0, 0};
    if (tree_.ndim == 3) {
        if (rev) return nullptr;  // RADIANCE does not sample 3-D trees by reciprocity
        c[0] = (.5 - kTiny) - .5 * std::sqrt(in.x * in.x + in.y * in.y);
    } else if (rev) {
        diskToSquare(in.x, in.y, c);  // the light leaves along the tree's -incident
    } else {
        diskToSquare(-in.x, -in.y, c);
    }
    for (int i = 0; i < nic_; ++i)
        c[i] = std::clamp(std::floor(c[i] / quantum_) * quantum_ + .5 * quantum_, .5 * quantum_,
                          1 - .5 * quantum_);
    return findOrBuild(rev ? 1 : 0, c);
}

size_t TreeDistribution::slotOf(const double c[2]) const {
    const int res = 1 << slotBits_;
    size_t s = 0;
    for (int i = 0; i < nic_; ++i)
        s = s * res + size_t(std::clamp(static_cast<int>(c[i] * res), 0, res - 1));
    return s;
}

// Lock-free when the table exists; otherwise built once under the mutex.
const CDist* TreeDistribution::findOrBuild(int mode, const double c[2]) const {
    const Cache& cache = cache_[mode];
    const size_t s = slotOf(c);
    for (const CDist* d = cache.slots[s].load(std::memory_order_acquire); d; d = d->next)
        if (d->serves(c, nic_)) return d;
    std::lock_guard<std::mutex> lock(buildMutex_);
    for (const CDist* d = cache.slots[s].load(std::memory_order_acquire); d; d = d->next)
        if (d->serves(c, nic_)) return d;
    std::unique_ptr<CDist> cd = build(mode == 1, c);
    CDist* raw = cd.get();
    built_.push_back(std::move(cd));
    publish(cache, raw, s);
    return raw;
}

// A table whose incident cell spans whole slots goes into each of them; smaller ones
// are chained in the one slot holding them (incident cells nest, so never both).
void TreeDistribution::publish(const Cache& cache, CDist* cd, size_t slot) const {
    const int res = 1 << slotBits_;
    const double width = cd->clim[0][1] - cd->clim[0][0];
    if (width * res < 1 - 1e-9) {
        cd->next = cache.slots[slot].load(std::memory_order_relaxed);
        cache.slots[slot].store(cd, std::memory_order_release);
        return;
    }
    int lo[2] = {0, 0}, hi[2] = {1, 1};
    for (int i = 0; i < nic_; ++i) {
        lo[i] = static_cast<int>(std::lround(cd->clim[i][0] * res));
        hi[i] = std::min(static_cast<int>(std::lround(cd->clim[i][1] * res)), res);
    }
    for (int a = lo[0]; a < hi[0]; ++a)
        for (int b = lo[1]; b < hi[1]; ++b) {
            auto& p = cache.slots[nic_ == 2 ? size_t(a) * res + b : size_t(a)];
            if (!p.load(std::memory_order_relaxed)) p.store(cd, std::memory_order_release);
        }
}

// make_cdist: the leaves crossed by the incident position, located on the outgoing
// square (mirrored when the outgoing side is the tree's incident one).
std::unique_ptr<CDist> TreeDistribution::build(bool rev, const double c[2]) const {
    struct Cell {
        uint32_t hilbert, wid;
        float value;
    };
    std::vector<Cell> cells;
    double pos[4] = {0, 0, 0, 0};
    for (int i = 0; i < nic_; ++i) pos[i + (rev ? 2 : 0)] = c[i];
    const unsigned mask = ((1u << nic_) - 1) << (rev ? 2 : 0);
    const int outDim = rev ? 0 : nic_;
    uint32_t wmin = 1u << kHilbertBits, wmax = 0;
    tree_.traverse(pos, mask, [&](float v, const double* cmin, double csiz) {
        double u = cmin[outDim], w = cmin[outDim + 1];
        if (rev) u = 1 - u - csiz, w = 1 - w - csiz;
        const auto wid = static_cast<uint32_t>(csiz * kHilbertScale + .5);
        const auto bx = static_cast<uint32_t>(u * kHilbertScale + .5);
        const auto by = static_cast<uint32_t>(w * kHilbertScale + .5);
        const uint64_t run = uint64_t(wid) * wid;
        cells.push_back({static_cast<uint32_t>(hilbertIndex(bx, by) & ~(run - 1)), wid, v});
        wmin = std::min(wmin, wid);
        wmax = std::max(wmax, wid);
    });
    std::sort(cells.begin(), cells.end(),
              [](const Cell& a, const Cell& b) { return a.hilbert < b.hilbert; });
    auto cd = std::make_unique<CDist>();
    const double scale = wmin / kHilbertScale;
    for (int i = 0; i < nic_; ++i) {
        cd->clim[i][0] = std::floor(c[i] / scale) * scale;
        cd->clim[i][1] = cd->clim[i][0] + scale;
    }
    if (nic_ == 1) cd->clim[1][0] = cd->clim[0][0], cd->clim[1][1] = cd->clim[0][1];
    cd->minWidth = scale;
    cd->maxWidth = wmax / kHilbertScale;
    cd->outSide = !rev ? side_ : (side_ == Side::XmitBack ? Side::XmitFront : Side::XmitBack);
    double total = 1e-20;
    for (const Cell& e : cells) total += e.value * double(e.wid) * e.wid;
    const double toCuml = kCumlMax / total;
    cd->cells.reserve(cells.size() + 1);
    double sum = 0;
    for (const Cell& e : cells) {
        cd->cells.push_back({e.hilbert, static_cast<uint32_t>(toCuml * sum + .5)});
        sum += e.value * double(e.wid) * e.wid;
    }
    cd->cells.push_back({0, UINT32_MAX});
    cd->cTotal = total * kPi / (kHilbertScale * kHilbertScale);
    return cd;
}

bool TreeDistribution::sample(const Vec3& in, double x, double y, Vec3& out) const {
    const CDist* cd = cdist(in);
    if (!cd || cd->cTotal <= 1e-6) return false;
    const auto& cells = cd->cells;
    const double target = std::clamp(x, 0.0, kBelowOne) * kCumlMax;
    size_t lo = 0, hi = cells.size() - 1;  // cells[lo].cuml <= target < cells[hi].cuml
    while (hi - lo > 1) {
        const size_t mid = (lo + hi) / 2;
        (target >= cells[mid].cuml ? lo : hi) = mid;
    }
    if (target >= cells[hi].cuml) return false;  // not for x in [0, 1)
    const double t = (target - cells[lo].cuml) / double(cells[hi].cuml - cells[lo].cuml);
    const uint64_t end = hi + 1 == cells.size() ? uint64_t(1) << 32 : cells[hi].hilbert;
    const uint64_t run = end - cells[lo].hilbert;
    const uint32_t wid = 1u << (std::countr_zero(run) / 2);
    uint32_t hx, hy;
    hilbertPoint(cells[lo].hilbert, hx, hy);
    const double yy = std::clamp(y, 0.0, kBelowOne);
    const double u = ((hx & ~(wid - 1)) + t * wid) / kHilbertScale;
    const double v = ((hy & ~(wid - 1)) + yy * wid) / kHilbertScale;
    double dx, dy;
    squareToDisk(u, v, dx, dy);
    const double z2 = 1 - dx * dx - dy * dy;
    double z = std::sqrt(z2 > 0 ? z2 : 0);
    if (cd->outSide == Side::ReflBack || cd->outSide == Side::XmitFront) z = -z;
    out = {dx, dy, z};
    if (tree_.ndim == 3) out = spinZ(out, std::atan2(-in.y, -in.x));
    return true;
}

// ---------------------------------------------------------------------------------
// Loading (SDloadTre).

struct SetData {
    std::optional<Tree> tree, u, v;  // Y, and CIE-u, CIE-v where given
    Side side = Side::ReflFront;
};

// The Lambertian part of a coloured tree (bsdf_t.c subtract_min_RGB): the smallest RGB
// over the Y tree's live leaves (u' v' read at each leaf's centre), taken out of Y where
// its brightness exceeds .01/pi. Returns it as a reflectance (pi times), or black.
Color subtractMinimumRgb(Tree& y, const Tree& u, const Tree& v) {
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    const double origin[4] = {0, 0, 0, 0};
    y.traverse(origin, 0, [&](float val, const double* cmin, double csiz) {
        if (y.ndim == 3 && cmin[0] >= .5) return;  // the unused half of a 3-D tree
        double pos[4], w;
        for (int i = 0; i < 4; ++i) pos[i] = cmin[i] + .5 * csiz;
        const Color c = rgbOfYuv(val, u.lookup(pos, w), v.lookup(pos, w));
        for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], c[i]);
    });
    const Color m{lo[0], lo[1], lo[2]};
    const double ymin = m.brightness();
    if (!(ymin > .01 / kPi) || !(ymin < HUGE_VAL)) return {};
    for (float& val : y.values) val = std::max(0.0f, static_cast<float>(val - ymin));
    return m;
}

// RADIANCE's names are WINDOW's with front and back swapped.
int setIndex(const pugi::xml_node& dir) {
    if (textIs(dir, "Transmission Front")) return 3;  // tb
    if (textIs(dir, "Transmission Back")) return 2;   // tf
    if (textIs(dir, "Reflection Front")) return 1;    // rb
    if (textIs(dir, "Reflection Back")) return 0;     // rf
    return -1;
}

// get_extrema: the smallest cell's projected solid angle and the largest
// directional-hemispherical value over incident boxes at least 1/32 wide.
void extrema(const Tree& tree, ScatteringSet& set) {
    double step = tree.smallestLeaf();
    set.minProjSA = kPi * step * step;
    step = std::max(step, 1.0 / 32);
    double best = 0;
    double bmin[4] = {0, 0, 0, 0}, bmax[4] = {1, 1, 1, 1};
    const double end0 = tree.ndim == 3 ? .5 - kTiny : 1 - kTiny;
    for (bmin[0] = 0; bmin[0] < end0; bmin[0] += step) {
        bmax[0] = bmin[0] + step;
        if (tree.ndim == 3) {
            best = std::max(best, tree.boxAverage(0, bmin, bmax));
            continue;
        }
        for (bmin[1] = 0; bmin[1] < 1 - kTiny; bmin[1] += step) {
            bmax[1] = bmin[1] + step;
            best = std::max(best, tree.boxAverage(0, bmin, bmax));
        }
    }
    set.maxHemi = kPi * best;
}

// subtract_min_Y: the minimum becomes the Lambertian part unless it is negligible
// (<= .01/pi) or so large (>= 1.5/pi) that the data are not worth splitting.
double subtractMinimum(Tree& tree) {
    const float vmaxmin = static_cast<float>(1.5 / kPi);
    const float vmin = tree.liveMinimum();
    if (vmin >= vmaxmin || vmin <= .01 / kPi) return 0;
    for (float& v : tree.values)
        if ((v -= vmin) < 0) v = 0;
    return kPi * vmin;
}

}  // namespace

void loadTensorTree(const pugi::xml_node& layer, const XmlContext& ctx, BsdfData& sd) {
    const pugi::xml_node ids = layer.child("DataDefinition").child("IncidentDataStructure");
    const int ndim = textIs(ids, "TensorTree3") ? 3 : textIs(ids, "TensorTree4") ? 4 : 0;
    if (!ndim) ctx.fail(ids ? ids : layer, "unsupported IncidentDataStructure for a tensor tree");
    std::array<SetData, 4> sets;
    const Side sides[4] = {Side::ReflFront, Side::ReflBack, Side::XmitFront, Side::XmitBack};
    for (int i = 0; i < 4; ++i) sets[i].side = sides[i];
    for (pugi::xml_node wd : layer.children("WavelengthData")) {
        const pugi::xml_node wl = wd.child("Wavelength");
        std::optional<Tree> SetData::*channel = textIs(wl, "Visible") ? &SetData::tree
                                                : textIs(wl, "CIE-u") ? &SetData::u
                                                : textIs(wl, "CIE-v") ? &SetData::v
                                                                      : nullptr;
        if (!channel) continue;
        for (pugi::xml_node block : wd.children("WavelengthDataBlock")) {
            const int which = setIndex(block.child("WavelengthDataDirection"));
            if (which >= 0) sets[which].*channel = parseScatteringData(block, ndim, ctx);
        }
    }
    std::optional<ScatteringSet>* targets[4] = {&sd.rf, &sd.rb, &sd.tf, &sd.tb};
    Color lamb[4];
    for (int i = 0; i < 4; ++i) {
        SetData& d = sets[i];
        if (!d.tree) continue;
        ScatteringSet set;
        extrema(*d.tree, set);  // before the split, as RADIANCE
        const bool colour = d.u && d.v;
        Color minRgb;
        if (colour)
            lamb[i] = (minRgb = subtractMinimumRgb(*d.tree, *d.u, *d.v)) * kPi;
        else
            lamb[i] = Color::grey(subtractMinimum(*d.tree));
        set.maxHemi -= lamb[i].brightness();
        auto dist = std::make_unique<TreeDistribution>(std::move(*d.tree), d.side);
        if (colour) dist->setColour(std::move(*d.u), std::move(*d.v), minRgb);
        set.components.push_back(std::move(dist));
        *targets[i] = std::move(set);
    }
    sd.rLambFront = lamb[0];
    sd.rLambBack = lamb[1];
    sd.tLambFront = lamb[2];
    sd.tLambBack = lamb[3];
    if (!sd.tb)
        sd.tLambBack = sd.tLambFront;  // one transmission serves both ways
    else if (!sd.tf)
        sd.tLambFront = sd.tLambBack;
}

}  // namespace rp::bsdf::detail
