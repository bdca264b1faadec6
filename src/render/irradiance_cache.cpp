// The irradiance cache's storage and lookup (see irradiance_cache.h).
//
// Why a multi-level hash grid rather than RADIANCE's octree: we are not given the scene
// cube's origin, and a grid keyed by hashed cell coordinates needs none; every level's
// cells are twice the size of the one below, and a record lives in the finest level
// whose cells are at least twice its reach (aa R_i, the largest distance a lookup
// accepts), linked into every cell its reach overlaps (at most 2x2x2). A query
// therefore probes one cell per level in use. Each link copies what the first tests
// need (position, radius, level, weight) into one cache line, so rejecting a candidate
// does not touch the record itself.
//
// Why our own hash table rather than tbb::concurrent_unordered_map: a lookup makes one
// find per level on the hottest path of the renderer, and TBB's split-ordered lists cost
// more per find than a flat table. Ours is open addressing with linear probing; readers
// take no lock: a slot's cell pointer is stored before its key (release), and a full
// table is replaced by a doubled copy published through an atomic pointer, the old one
// kept alive until the cache dies so that readers still probing it stay safe. Inserts take a mutex:
// each follows a hemisphere of hundreds of rays, so they are rare.
#include "render/irradiance_cache.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <deque>
#include <optional>

#include "render/ambient_hemisphere.h"

namespace rp::render {

namespace {

constexpr int kLevels = 64;

uint64_t mixKey(uint64_t h) {
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    return h ^ (h >> 31);
}

// Cells are found by a 64-bit hash of (level, x, y, z) alone; two cells hashing alike
// would share a list (candidates are tested by distance anyway; only a record whose two
// cells collide could be counted twice), with odds of about 2^-64 per pair.
uint64_t cellKey(int level, int64_t x, int64_t y, int64_t z) {
    uint64_t h = mixKey(uint64_t(x) ^ (uint64_t(level) << 58));
    h = mixKey(h ^ uint64_t(y));
    return mixKey(h ^ (uint64_t(z) * 0x9e3779b97f4a7c15ULL));
}

int64_t cellIndex(double t) {
    constexpr double kLimit = 4.0e18;  // far beyond any sane scene; keeps the cast defined
    return int64_t(std::floor(std::clamp(t, -kLimit, kLimit)));
}

// RADIANCE compat (ambient.c plugaleak): a record whose corral flags the query's
// direction is tested with a ray from the query toward the record's normal line, aimed
// 20 degrees above the query's tangent plane (high enough to miss the small geometry
// near the record); an occluder on it plugs the leak.
bool leaks(const AmbientRecord& r, const CacheQuery& q) {
    Vec3 u, v;
    tangentFrame(r.normal, u, v);
    const Vec3 toQuery = q.point - r.position;
    double angle = std::atan2(dot(toQuery, v), dot(toQuery, u));
    if (angle < 0) angle += 2 * kPi;
    const int sector = std::min(31, int(angle * (16 / kPi)));
    if (!(r.corral >> sector & 1u)) return false;
    constexpr double kCos70Squared = 0.1169778;
    const Vec3 vdif = r.position - q.point;
    const double normdot = dot(r.normal, q.normal), ndotd = dot(vdif, q.normal);
    const double nadotd = dot(vdif, r.normal);
    const double a = normdot * normdot - kCos70Squared;
    const double b = 2 * (normdot * ndotd - nadotd * kCos70Squared);
    const double c = ndotd * ndotd - dot(vdif, vdif) * kCos70Squared;
    const double disc = b * b - 4 * a * c;
    if (a == 0 || !(disc > 0)) return true;  // RADIANCE: "should rarely happen"
    const double root = std::sqrt(disc);
    const double t = std::max((-b - root) / (2 * a), (-b + root) / (2 * a));
    if (t <= 1e-6) return false;  // the behind test's business
    return q.leaks->blocked(q.origin, r.position + r.normal * t);
}

}  // namespace

// One cell's entry for a record: the data the cheap tests need, in one cache line.
struct alignas(64) IrradianceCache::Node {
    const Node* next = nullptr;  // written once before the node is published
    Vec3 position;
    double radius = 0;
    double weight = 1;
    int level = 0;
    const AmbientRecord* rec = nullptr;
};

struct IrradianceCache::Cells {
    struct Cell {
        std::atomic<const Node*> head{nullptr};
    };
    struct Table {
        explicit Table(size_t capacity) : mask(capacity - 1), keys(capacity), cells(capacity) {}
        size_t mask;
        std::vector<std::atomic<uint64_t>> keys;  // 0: empty slot
        std::vector<std::atomic<Cell*>> cells;
    };
    std::atomic<const Table*> current{nullptr};
    std::vector<std::unique_ptr<Table>> tables;  // every table ever published
    std::vector<std::unique_ptr<Cell>> owned;
    std::deque<AmbientRecord> records;  // stable addresses
    std::deque<Node> nodes;
    size_t used = 0;

    static uint64_t slotKey(uint64_t key) { return key ? key : 1; }

    const Cell* find(uint64_t key) const {
        const Table* t = current.load(std::memory_order_acquire);
        key = slotKey(key);
        for (size_t i = key & t->mask;; i = (i + 1) & t->mask) {
            uint64_t k = t->keys[i].load(std::memory_order_acquire);
            if (k == key) return t->cells[i].load(std::memory_order_relaxed);
            if (k == 0) return nullptr;
        }
    }

    static void put(Table& t, uint64_t key, Cell* cell) {
        for (size_t i = key & t.mask;; i = (i + 1) & t.mask)
            if (t.keys[i].load(std::memory_order_relaxed) == 0) {
                t.cells[i].store(cell, std::memory_order_relaxed);
                t.keys[i].store(key, std::memory_order_release);
                return;
            }
    }

    // Caller holds the insert mutex.
    Cell& findOrAdd(uint64_t key) {
        if (const Cell* c = find(key)) return const_cast<Cell&>(*c);
        key = slotKey(key);
        Table* t = tables.back().get();
        if (2 * (used + 1) > t->mask + 1) {  // keep the load under 1/2: short probes
            auto bigger = std::make_unique<Table>(2 * (t->mask + 1));
            for (size_t i = 0; i <= t->mask; ++i)
                if (uint64_t k = t->keys[i].load(std::memory_order_relaxed))
                    put(*bigger, k, t->cells[i].load(std::memory_order_relaxed));
            t = bigger.get();
            tables.push_back(std::move(bigger));
            current.store(t, std::memory_order_release);
        }
        owned.push_back(std::make_unique<Cell>());
        Cell* cell = owned.back().get();
        put(*t, key, cell);
        ++used;
        return *cell;
    }
};

IrradianceCache::IrradianceCache(double accuracy, double minRadius, double sceneSize)
    : accuracy_(accuracy), minRadius_(minRadius), cells_(std::make_unique<Cells>()) {
    double reach =
        accuracy_ * (minRadius > 0 ? minRadius : (sceneSize > 0 ? sceneSize / 1024 : 1e-3));
    cell0_ = std::max(2 * reach, 1e-12);
    cells_->tables.push_back(std::make_unique<Cells::Table>(1024));
    cells_->current.store(cells_->tables.back().get(), std::memory_order_release);
}

IrradianceCache::~IrradianceCache() = default;

std::optional<Color> extrapolate(const AmbientRecord& rec, const Vec3& p, const Vec3& n,
                                 bool gradients) {
    // RADIANCE compat (ambient.c extambient): the factor is clamped to [0.05, 20], and a
    // record whose extrapolation falls to the floor is not used at all (counting it as
    // black with its full weight would darken its neighbours' estimate).
    double f = 1;
    if (gradients) {
        f += dot(rec.gradPosition, p - rec.position);
        f += dot(rec.gradDirection, cross(rec.normal, n));
    }
    if (!(f > 0.05)) return std::nullopt;
    return rec.value * std::min(f, 20.0);
}

namespace {

double maxNormalAngle(double accuracy, double weight) {
    // RADIANCE compat (ambient.c sumambient): 10 degrees plus -aa radians, widened toward
    // 90 degrees for light rays, whose error matters less.
    const double base = 10 * kPi / 180 + accuracy;
    return weight < 0.6 ? (base - kPi / 2) * std::pow(weight, 0.13) + kPi / 2 : base;
}

}  // namespace

bool IrradianceCache::lookup(const CacheQuery& q, Color& out) const {
    // RADIANCE compat (RADIANCE 5 ambient.c sumambient): a record is used where the
    // query lies within -aa of its radius (|P - Pi| / Ri < aa, the distance off its
    // plane included) and its normal within maxNormalAngle; each is weighted by the
    // product of two hat functions falling to zero at those limits. Ward's 1/e weight
    // (RADIANCE 3) let the nearest record dominate: its noise passed whole into every
    // point beside it (the large-ground room's work-plane mean at -ab 5 spread twice as
    // wide between runs as RADIANCE 5's), and its edges needed a jittered limit to hide.
    const double aa = accuracy_;
    const double aa2 = aa * aa;
    const double maxAngle = maxNormalAngle(aa, q.weight);
    const double maxAngle2 = maxAngle * maxAngle;
    // RADIANCE compat ("modified ray behind test"): tolerance in scene units.
    const double behindTolerance = minRadius_ * aa + 1e-3;
    Color sum;
    double weightSum = 0;

    auto consider = [&](const Node& n) {
        const Vec3 d = q.point - n.position;
        const double t2 = dot(d, d) / (n.radius * n.radius);
        if (t2 >= aa2) return;
        // A record from a deeper bounce, or from the same one for a much lighter ray,
        // is less accurate than wanted.
        if (n.level > q.level || (n.level == q.level && n.weight < 0.9 * q.weight)) return;
        const AmbientRecord& r = *n.rec;
        const double cosAngle = dot(r.normal, q.normal);
        if (cosAngle <= 0) return;
        const double r2 = 2 - 2 * cosAngle;  // squared angle, nearly
        if (r2 >= maxAngle2) return;
        // Records in front of the point see a different hemisphere.
        if (dot(d, r.normal) < -behindTolerance) return;
        if (r.corral && q.leaks && leaks(r, q)) return;
        const std::optional<Color> v = extrapolate(r, q.point, q.normal, useGradients_);
        if (!v) return;
        const double w = (1 - std::sqrt(r2) / maxAngle) * (1 - std::sqrt(t2) / aa);
        sum += *v * w;
        weightSum += w;
    };

    uint64_t used = levelsUsed_.load(std::memory_order_acquire);
    while (used) {
        int level = std::countr_zero(used);
        used &= used - 1;
        double cell = std::ldexp(cell0_, level);
        const Cells::Cell* c =
            cells_->find(cellKey(level, cellIndex(q.point.x / cell), cellIndex(q.point.y / cell),
                                 cellIndex(q.point.z / cell)));
        if (!c) continue;
        for (const Node* n = c->head.load(std::memory_order_acquire); n; n = n->next) consider(*n);
    }
    if (weightSum <= 1e-6) return false;
    out = sum / weightSum;
    return true;
}

void IrradianceCache::insert(const AmbientRecord& rec, bool isNew) {
    const double reach = accuracy_ * rec.radius;
    int level = 0;
    double cell = cell0_;
    while (cell < 2 * reach && level < kLevels - 1) {
        cell *= 2;
        ++level;
    }
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = cellIndex((rec.position[a] - reach) / cell);
        hi[a] = std::min(cellIndex((rec.position[a] + reach) / cell), lo[a] + 1);
    }
    std::lock_guard<std::mutex> lock(insertMutex_);
    const AmbientRecord* stored = &cells_->records.emplace_back(rec);
    for (int64_t x = lo[0]; x <= hi[0]; ++x)
        for (int64_t y = lo[1]; y <= hi[1]; ++y)
            for (int64_t z = lo[2]; z <= hi[2]; ++z) {
                Node& node = cells_->nodes.emplace_back();
                node.position = rec.position;
                node.radius = rec.radius;
                node.weight = rec.weight;
                node.level = rec.level;
                node.rec = stored;
                std::atomic<const Node*>& head = cells_->findOrAdd(cellKey(level, x, y, z)).head;
                node.next = head.load(std::memory_order_relaxed);
                head.store(&node, std::memory_order_release);
            }
    levelsUsed_.fetch_or(uint64_t(1) << level, std::memory_order_release);
    count_.fetch_add(1, std::memory_order_relaxed);
    if (isNew) new_.push_back(stored);
}

std::vector<AmbientRecord> IrradianceCache::newRecords() const {
    std::lock_guard<std::mutex> lock(insertMutex_);
    std::vector<AmbientRecord> out;
    out.reserve(new_.size());
    for (const AmbientRecord* r : new_) out.push_back(*r);
    return out;
}

}  // namespace rp::render
