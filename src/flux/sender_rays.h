// The rays rfluxmtx sends into rcontrib for a sender (RADIANCE rfluxmtx.c sample_origin,
// ssamp_poly, ssamp_ring and the sample_* generators): for each bin of the sender's
// basis in turn, -c rays leaving the back of the sender in directions stratified over
// the bin, from points on its surfaces chosen in proportion to their area projected
// along the ray. Served as a stream of binary doubles (rcontrib -fd input), made one
// bin at a time so that a large basis never sits in memory whole.
#pragma once

#include <cstdint>
#include <exception>
#include <memory>
#include <streambuf>
#include <vector>

#include "flux/flux_surfaces.h"
#include "util/rng.h"

namespace rp::flux {

// Points on a sender's polygons and rings.
class SenderSurfaces {
public:
    explicit SenderSurfaces(const FluxGroup& sender);
    ~SenderSurfaces();

    // A point on the surfaces for a ray travelling `dir` (unit), from x in [0,1): the
    // surface by projected area, the point inside it uniform by area. Throws InputError
    // for a direction that no surface faces away from (RADIANCE's "internal - sample
    // behind sender").
    Vec3 origin(const Vec3& dir, double x) const;

    struct Shape;  // one polygon or ring (sender_rays.cpp)

private:
    std::vector<std::unique_ptr<Shape>> shapes_;
    mutable std::vector<double> projected_;
};

// Streams the sender's rays: bins 0 .. n-1, `samples` rays each, origin then direction
// as six native doubles. Deterministic: each bin draws from its own Rng stream of `seed`.
class SenderRayBuffer : public std::streambuf {
public:
    SenderRayBuffer(const FluxGroup& sender, int samples, uint64_t seed);
    int bins() const { return bins_; }
    // An error met while making rays (which ends the stream early, as an istream cannot
    // pass it on): rethrow it in place of what the reader then reports.
    std::exception_ptr error() const { return error_; }

protected:
    int_type underflow() override;

private:
    void fillBin(int bin);
    const FluxGroup& sender_;
    SenderSurfaces surfaces_;
    int samples_;
    uint64_t seed_;
    int bins_;
    int next_ = 0;
    std::vector<double> rays_;
    std::exception_ptr error_;
};

}  // namespace rp::flux
