// Ward's irradiance cache (RADIANCE ambient.c): records of hemisphere estimates with a
// validity radius and Ward & Heckbert gradients, found by position for weighted
// extrapolation. Lookups take no lock and allocate nothing; inserts take a mutex (each
// follows a whole hemisphere computation). How records are computed and when one is made
// lives in ambient.cpp.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "util/color.h"
#include "util/vec.h"

namespace rp::render {

// RADIANCE's AMBVAL, in double precision in memory. The fields a lookup tests first
// (position, radius, level, weight) come first so that rejecting a candidate touches
// one cache line.
struct AmbientRecord {
    Vec3 position;
    double radius = 0;   // validity radius R_i of Ward's error estimate
    int level = 0;       // ambient level of the ray that made it
    double weight = 1;   // RADIANCE's record weight (AVGREFL^level, or from the ray)
    Vec3 normal;         // unit
    Color value;         // mean radiance of the hemisphere (irradiance / pi)
    Vec3 gradPosition;   // translational gradient of brightness(value), relative (1/length)
    Vec3 gradDirection;  // rotational gradient, relative: factor 1 + g . (N_i x N)
    // RADIANCE's corral (ambcomp.c ambcorral): bit s set where a surface near the horizon
    // lies within the record's reach in azimuth sector s (32 sectors of pi/16 about the
    // normal, from tangentFrame's u axis). A query in such a sector may be behind that
    // surface: the lookup tests (CacheQuery::leaks).
    uint32_t corral = 0;
};

// Whether an opaque surface lies between a query and a record that might have leaked
// through it (RADIANCE ambient.c plugaleak). Implemented by the renderer per query.
class LeakTest {
public:
    virtual ~LeakTest() = default;
    // Any surface that stops light (not void, transparent, a thick BSDF's proxy or
    // clipped) on the segment from `from` (off the query's surface) to `to`.
    virtual bool blocked(const Vec3& from, const Vec3& to) = 0;
};

// The query of one lookup.
struct CacheQuery {
    Vec3 point;
    Vec3 normal;
    int level = 0;
    double weight = 1;          // the ray's weight (scales the normal error, as RADIANCE)
    Vec3 origin;                // point moved off its surface, where leak tests start
    LeakTest* leaks = nullptr;  // null: records are not tested for leaks
};

class IrradianceCache {
public:
    // `accuracy`: -aa (> 0). `minRadius`: the smallest radius computed records get
    // (scene size / -ar, 0 if -ar 0) and `sceneSize`: used to size the grid cells.
    IrradianceCache(double accuracy, double minRadius, double sceneSize);
    ~IrradianceCache();
    IrradianceCache(const IrradianceCache&) = delete;
    IrradianceCache& operator=(const IrradianceCache&) = delete;

    // Weighted extrapolation of every record that covers the query (RADIANCE 5
    // sumambient): within aa R_i of the record and within 10 degrees plus aa radians of
    // its normal (wider for light rays), weighted by hat functions of both; records in
    // front of the point, computed at a deeper level or for a much lighter ray, seen past
    // an occluder in their corral (q.leaks), or whose gradients extrapolate to nearly
    // nothing are skipped. Returns false when no record passes (the caller computes a new
    // one).
    bool lookup(const CacheQuery& q, Color& out) const;

    // Adds a record; safe concurrently with lookups and other inserts. `isNew` records
    // are also kept, in insertion order, for newRecords().
    void insert(const AmbientRecord& rec, bool isNew = true);

    long size() const { return count_.load(std::memory_order_relaxed); }
    // Records inserted with isNew, in order (a copy: taken under the insert mutex).
    std::vector<AmbientRecord> newRecords() const;

    // Tests compare extrapolation with and without gradients.
    void setUseGradients(bool on) { useGradients_ = on; }

private:
    struct Node;
    struct Cells;
    double accuracy_;
    double minRadius_;
    double cell0_;  // edge of the finest grid cells
    bool useGradients_ = true;
    std::unique_ptr<Cells> cells_;
    std::atomic<uint64_t> levelsUsed_{0};  // bit l: some record lives in grid level l
    std::atomic<long> count_{0};
    mutable std::mutex insertMutex_;
    std::vector<const AmbientRecord*> new_;
};

// Value of `rec` extrapolated to point p with normal n (RADIANCE extambient): the first-
// order Taylor expansion with both gradients, at most 20 times the value; nothing where
// it falls below 0.05 times the value (the record is not used there).
std::optional<Color> extrapolate(const AmbientRecord& rec, const Vec3& p, const Vec3& n,
                                 bool gradients);

}  // namespace rp::render
