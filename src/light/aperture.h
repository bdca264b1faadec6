// Emission apertures: the cone of directions a point of a light source emits into (the
// hemisphere over its surface, a spotlight cone, the disk of a distant source), the
// exact projected solid angle of a cone over a surface, sampling directions in
// proportion to cos(theta_surface) within a cone, and tabulated direction
// distributions (-dp) for modified sources and ports. No scene or partition knowledge.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "util/color.h"
#include "util/rng.h"
#include "util/vec.h"

namespace rp::light {

constexpr double kFtiny = 1e-6;  // RADIANCE FTINY

// A cone of directions about unit `axis` with half angle acos(cosHalf); cosHalf = 0 is a
// hemisphere, -1 the whole sphere.
struct Cone {
    Vec3 axis;
    double cosHalf = 0;
    double solidAngle() const { return 2 * kPi * (1 - cosHalf); }
};

// Integral over the cone (axis a, half angle acos(cosHalf)) of max(0, w.n) dw: what a
// Lambertian-in-the-cone emitter of unit radiance sends out per unit area of a surface
// with unit normal n. pi for a hemisphere about n; pi sin^2(theta) (a.n) for a cone
// wholly above the surface. Exact to ~1e-12: the azimuthal integral is closed form and
// the polar one is Gauss-Legendre on pieces split where the integrand has kinks.
double projectedSolidAngle(const Vec3& a, double cosHalf, const Vec3& n);
inline double projectedSolidAngle(const Cone& c, const Vec3& n) {
    return projectedSolidAngle(c.axis, c.cosHalf, n);
}

// A unit direction w in the cone with density proportional to max(0, w.n), exactly
// (inversion when the cone is centred on n, else rejection from the cheaper of a
// cosine-weighted hemisphere and a uniform cone). Requires projectedSolidAngle > 0.
Vec3 sampleProjectedCone(const Cone& c, const Vec3& n, Rng& rng);

// sampleProjectedCone(Cone{n, 0}, n, rng), the cosine-weighted hemisphere about unit n,
// with n's coneFrame u, v given, so that a caller emitting many photons about one normal
// (a flat light source) computes the frame once. The same direction, bit for bit.
Vec3 sampleCosineHemisphere(const Vec3& n, const Vec3& u, const Vec3& v, Rng& rng);

// Uniform direction in the cone (density 1 / solidAngle).
Vec3 sampleUniformCone(const Cone& c, Rng& rng);

// Orthonormal u, v completing unit w (fixed for a given w).
void coneFrame(const Vec3& w, Vec3& u, Vec3& v);

// A tabulated emission distribution over a cone, RADIANCE's -dp grid (pmapsrc.c
// initPhotonEmission): nTheta bands uniform in cos(theta) times nPhi sectors, about
// sqrt(2 dp (1-cosHalf)) x pi times that, so cells have equal solid angle. Cells hold
// the RGB value (radiance x modifier x cos_surface x visibility) at their centre
// direction; only non-zero cells are kept, with a CDF over their mean.
class DirectionTable {
public:
    // f(w) -> Color for a unit direction w in the cone (evaluated once per cell centre).
    template <class F>
    DirectionTable(const Cone& cone, double samplesPerSr, F f) {
        init(cone, samplesPerSr);
        for (uint32_t t = 0; t < nTheta_; ++t)
            for (uint32_t p = 0; p < nPhi_; ++p) add(t, p, f(centre(t, p)));
    }

    // The same grid with each cell's value the mean of f(w, k) over k = 0..n-1, the w
    // on a regular grid over the cell (ceil(sqrt n) columns): for values that vary within
    // a cell, such as what a port sees outside (mkpmap -apE), where a horizon crossing a
    // cell then splits its samples as it splits the cell. `k` lets the caller vary the
    // rest of the sample (a point on the port) with it.
    struct Averaged {};
    template <class F>
    DirectionTable(Averaged, const Cone& cone, double samplesPerSr, int n, F f) {
        init(cone, samplesPerSr);
        const int cols = int(std::ceil(std::sqrt(double(n))));
        const int rows = (n + cols - 1) / cols;
        for (uint32_t t = 0; t < nTheta_; ++t)
            for (uint32_t p = 0; p < nPhi_; ++p) {
                Color sum;
                for (int k = 0; k < n; ++k)
                    sum +=
                        f(cellDirection(t, p, (k / cols + 0.5) / rows, (k % cols + 0.5) / cols), k);
                add(t, p, sum * (1.0 / n));
            }
    }

    // Integral of the tabulated value over the cone (sum of cells x cell solid angle).
    const Color& integral() const { return integral_; }
    double cellSolidAngle() const { return cellSolidAngle_; }
    bool empty() const { return cells_.empty(); }
    size_t cellCount() const { return size_t(nTheta_) * nPhi_; }
    size_t keptCells() const { return cells_.size(); }

    struct Sample {
        Vec3 dir;
        Color value;  // of the chosen cell
    };
    // A direction from the table (cell by CDF, binary search; uniform within the cell).
    // `accept` (w) -> bool lets the caller re-jitter within the cell, e.g. to stay above
    // a surface; after 16 refusals the cell centre is used.
    template <class Accept>
    Sample sample(Rng& rng, Accept accept) const {
        const Cell& c = pick(rng.uniform());
        Vec3 w;
        for (int i = 0; i < 16; ++i) {
            w = cellDirection(c.theta, c.phi, rng.uniform(), rng.uniform());
            if (accept(w)) return {w, c.value()};
        }
        return {centre(c.theta, c.phi), c.value()};
    }

    // The same table without the cells whose centre direction fails `keep` (occlusion
    // seen from a port partition). Sets `changed` if any cell was dropped.
    template <class Keep>
    DirectionTable filtered(Keep keep, bool& changed) const {
        DirectionTable out = *this;
        out.cells_.clear();
        out.integral_ = {};
        for (const Cell& c : cells_)
            if (keep(centre(c.theta, c.phi))) out.add(c.theta, c.phi, c.value());
        changed = out.cells_.size() != cells_.size();
        return out;
    }

private:
    // Floats: a sky hemisphere at -dp 1000 has ~6,300 cells per table.
    struct Cell {
        uint16_t theta, phi;
        float cdf;  // cumulative mean value up to and including this cell
        float rgb[3];
        Color value() const { return {rgb[0], rgb[1], rgb[2]}; }
    };
    void init(const Cone& cone, double samplesPerSr);
    void add(uint32_t t, uint32_t p, const Color& value);
    Vec3 cellDirection(uint32_t t, uint32_t p, double ju, double jv) const;
    // cellDirection(t, p, 0.5, 0.5), computed once per grid (init) and shared by the
    // tables filtered from this one: a port's partitions each filter the port's table,
    // and recomputing the centres (sin, cos, a square root each) was a quarter of mkpmap
    // through the daylit office's window. Grids beyond kMaxKeptCentres cells (a -dp far
    // above practice) compute them when asked, as before.
    static constexpr size_t kMaxKeptCentres = size_t{1} << 20;
    Vec3 centre(uint32_t t, uint32_t p) const {
        return centres_ ? (*centres_)[size_t(t) * nPhi_ + p] : cellDirection(t, p, 0.5, 0.5);
    }
    const Cell& pick(double u) const;
    std::shared_ptr<const std::vector<Vec3>> centres_;

    Vec3 axis_, u_, v_;
    double cosHalf_ = 0;
    uint32_t nTheta_ = 1, nPhi_ = 1;
    double cellSolidAngle_ = 0;
    std::vector<Cell> cells_;
    Color integral_;
};

}  // namespace rp::light
