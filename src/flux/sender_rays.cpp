// Sender ray generation (see sender_rays.h).
#include "flux/sender_rays.h"

#include <cmath>
#include <span>

#include "bsdf/multi_sample.h"
#include "flux/basis.h"
#include "geometry/triangulate.h"

namespace rp::flux {

namespace {
constexpr double kFtiny = 1e-6;  // RADIANCE's FTINY
}

struct SenderSurfaces::Shape {
    const FluxSurface* surface;
    explicit Shape(const FluxSurface& s) : surface(&s) {}
    virtual ~Shape() = default;
    // A point uniform over the surface's area from x in [0,1).
    virtual Vec3 point(double x) const = 0;
};

namespace {

// A polygon cut into triangles, one picked by its share of the area and the point placed
// in it with the rest of x (rfluxmtx.c ssamp_poly).
class PolygonShape final : public SenderSurfaces::Shape {
public:
    explicit PolygonShape(const FluxSurface& s) : Shape(s) {
        std::vector<Vec3> loop;
        for (size_t i = 0; i + 2 < s.args.size(); i += 3)
            loop.push_back({s.args[i], s.args[i + 1], s.args[i + 2]});
        const Triangulation t = triangulatePolygon(loop, s.normal);
        double total = 0;
        for (const TriIndices& tri : t.triangles) {
            const Vec3 a = t.vertices[tri[0]], b = t.vertices[tri[1]], c = t.vertices[tri[2]];
            tris_.push_back({a, b - a, c - a, 0});
            total += 0.5 * length(cross(b - a, c - a));
            tris_.back().cumulative = total;
        }
        for (Tri& tri : tris_) tri.cumulative /= total;
    }

    Vec3 point(double x) const override {
        size_t i = 0;
        while (i + 1 < tris_.size() && x > tris_[i].cumulative) ++i;
        const double lo = i ? tris_[i - 1].cumulative : 0;
        double s[2];
        bsdf::multiSample2((x - lo) / (tris_[i].cumulative - lo), s);
        // Barycentric weights (r (1 - s0), r s0, 1 - r) with r = sqrt(s1): uniform in area.
        const double r = std::sqrt(s[1]);
        const Tri& t = tris_[i];
        return t.v0 + t.e1 * (s[0] * r) + t.e2 * (1 - r);
    }

private:
    struct Tri {
        Vec3 v0, e1, e2;
        double cumulative;  // area share of this triangle and those before it
    };
    std::vector<Tri> tris_;
};

// A disc or annulus: radius squared uniform between the two radii (rfluxmtx.c ssamp_ring).
class RingShape final : public SenderSurfaces::Shape {
public:
    explicit RingShape(const FluxSurface& s) : Shape(s) { orthonormalFrame(s.normal, u_, v_); }

    Vec3 point(double x) const override {
        const std::vector<double>& a = surface->args;
        double s[2];
        bsdf::multiSample2(x, s);
        const double r = std::sqrt(s[0] * (a[7] * a[7] - a[6] * a[6]) + a[6] * a[6]);
        const double phi = 2 * kPi * s[1];
        return Vec3{a[0], a[1], a[2]} + u_ * (r * std::cos(phi)) + v_ * (r * std::sin(phi));
    }

private:
    Vec3 u_, v_;
};

}  // namespace

SenderSurfaces::SenderSurfaces(const FluxGroup& sender) {
    for (const FluxSurface& s : sender.surfaces) {
        if (s.type == SurfaceType::Ring)
            shapes_.push_back(std::make_unique<RingShape>(s));
        else
            shapes_.push_back(std::make_unique<PolygonShape>(s));
    }
    projected_.resize(shapes_.size());
}

SenderSurfaces::~SenderSurfaces() = default;

Vec3 SenderSurfaces::origin(const Vec3& dir, double x) const {
    if (shapes_.size() == 1) {
        const FluxSurface& s = *shapes_[0]->surface;
        if (dot(s.normal, dir) >= kFtiny)
            throw InputError(s.loc, "internal - sample behind sender '" + s.name + "'");
        return shapes_[0]->point(x);
    }
    double total = 0;
    for (size_t i = 0; i < shapes_.size(); ++i) {
        const FluxSurface& s = *shapes_[i]->surface;
        projected_[i] = std::max(0.0, -dot(s.normal, dir) * s.area);
        total += projected_[i];
    }
    if (total < kFtiny * kFtiny)
        throw InputError(shapes_[0]->surface->loc, "internal - sample behind all sender elements");
    double t = total * x;
    size_t i = 0;
    while (i + 1 < shapes_.size() && t > projected_[i]) t -= projected_[i++];
    return shapes_[i]->point(std::min(t / projected_[i], 1.0));
}

SenderRayBuffer::SenderRayBuffer(const FluxGroup& sender, int samples, uint64_t seed)
    : sender_(sender),
      surfaces_(sender),
      samples_(samples),
      seed_(seed),
      bins_(basisBins(sender.basis, sender.params.size)) {}

void SenderRayBuffer::fillBin(int bin) {
    // One stream per bin: a bin's rays do not depend on how many bins came before.
    Rng rng(seed_, RngDomain::Sampling, uint64_t(bin));
    rays_.clear();
    rays_.reserve(size_t(samples_) * 6);
    const FluxGroup& g = sender_;
    for (int n = 0; n < samples_; ++n) {
        // Stratified along a space-filling curve through (origin, direction) space.
        const double x = (n + rng.uniform()) / samples_;
        const double jitter[3] = {rng.uniform(), rng.uniform(), rng.uniform()};
        double t[3];
        multiSample3(x, jitter, t);
        const Vec3 d = senderDirection(g.basis, g.params.size, bin, t[1], t[2]);
        const Vec3 dir = g.uAxis * d.x + g.vAxis * d.y + g.normal * d.z;
        const Vec3 org = surfaces_.origin(dir, t[0]);
        rays_.insert(rays_.end(), {org.x, org.y, org.z, dir.x, dir.y, dir.z});
    }
}

SenderRayBuffer::int_type SenderRayBuffer::underflow() {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (next_ >= bins_ || error_) return traits_type::eof();
    try {
        fillBin(next_++);
    } catch (...) {
        error_ = std::current_exception();
        return traits_type::eof();
    }
    char* begin = reinterpret_cast<char*>(rays_.data());
    setg(begin, begin, begin + rays_.size() * sizeof(double));
    return traits_type::to_int_type(*gptr());
}

}  // namespace rp::flux
