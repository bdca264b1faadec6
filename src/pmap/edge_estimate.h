// Edge-aware correction of a surface photon density estimate (rtrace/rpict -ape; radphoton's
// own, not RADIANCE's): the geometry of a disc cut by a straight light/shadow edge, and the
// fit of that model to the found photons' distances. Searching and the estimate itself
// (RADIANCE's photonDensity) live in density.h.
//
// The model: photons that fill a disc of radius R uniformly have u = s^2/R^2 uniform in
// [0, 1). A straight edge at signed distance delta R from the query (delta > 0: the query
// is lit; < 0: in the dark) lights the fraction a(u; delta) of the circle of squared
// radius u (edgeCircleFraction). The maximum likelihood delta gives the lit part of the
// disc, edgeDiscFraction(delta) = F/pi with F the circular segment's area, which then
// replaces the whole disc's area in the estimate, and says whether the query is lit.
//
// Distances only, because a search returns each photon's squared distance to the query,
// not its position (photon_store.h FoundPhoton). They show the dark side of an edge
// clearly: outside a caustic no photon lies nearer than the edge, a gap that uniform light
// leaves only by rare chance. The lit side within about R of an edge they hardly show (the
// circle of u < delta^2, fully lit, holds few photons), and there the estimate stays
// RADIANCE's; the photons' positions in the tangent plane (their centroid and the chord
// they stop at) would show it. A linear gradient leaves the radial profile uniform (it
// cancels over every circle), so the fit cannot take one for an edge; a point exactly on
// a sharp edge sees a uniform profile too, and there RADIANCE's estimate (half the lit
// density) is right.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace rp::pmap {

// Fraction of the unit disc on the lit side x < delta of a straight edge (the circular
// segment's area over pi): 0 for delta <= -1, 1/2 at 0, 1 for delta >= 1.
double edgeDiscFraction(double delta);

// Fraction of the circle of radius sqrt(u) (unit disc radii) on the lit side x < delta:
// 1 - acos(delta / sqrt(u)) / pi, with delta / sqrt(u) clamped to [-1, 1].
double edgeCircleFraction(double delta, double u);

// Probability that a photon spread uniformly over the lit part of the unit disc lies
// within squared radius u: u edgeDiscFraction(delta / sqrt(u)) / edgeDiscFraction(delta).
double edgeRadialCdf(double delta, double u);

// The fit of the edge model to one lookup.
struct EdgeFit {
    double delta = 1;  // edge offset in units of the radius; >= 1: no edge in the disc
    // Log likelihood of the best edge over that of a uniformly filled disc (>= 0).
    double logLikelihoodRatio = 0;
    // Multiplier for RADIANCE's estimate (edgeFactor): 1 where no edge is significant.
    double factor = 1;
};

// Thresholds on 2 x logLikelihoodRatio, the likelihood-ratio statistic. Up to `onset` the
// estimate is RADIANCE's (factor exactly 1), from `full` on the edge model's, in between a
// linear blend, so that the estimate does not jump as noise moves the statistic across
// one threshold. On uniformly filled discs the statistic passes 14 in 0.02-0.035 % of
// lookups for k = 10..100, 0.05 % at k = 200 and 0.1 % at 500, and 17 (half weight) in
// under 0.01 % up to k = 200 (10^5 and 2 x 10^4 trials; the test checks k = 50): inside a
// uniform region the estimate stays RADIANCE's, with RADIANCE's noise. A chance gap
// before the nearest photons cannot be told from a real edge just outside the disc's
// centre, and a false "dark" reading is a black dot in a rendering: a lower onset (10:
// 0.2 %) reads 0 at one search radius outside an edge more often, but dots the
// interior of a caustic (measured on tests/data/caustic_edge: 7 times more pixels below
// half their value than with 14 and 20).
struct EdgeParams {
    double onset = 14;
    double full = 20;
    // Half-width, in units of the radius, of the blend from dark (0) to lit (1) across
    // the fitted edge: a fit near delta = 0 says "on the edge", not on which side.
    double blur = 0.1;
};

// Fewer photons than this are never fitted (their profile says little).
constexpr size_t kMinEdgePhotons = 8;
// The pretest (edgeWorthFitting): k min(u) and the standardised mean of u.
constexpr double kPretestGap = 3;
constexpr double kPretestMean = 2;

// Whether `u` (squared distances over R^2, any order) departs enough from a uniformly
// filled disc for the fit to be worth its cost: k min(u) >= kPretestGap (the nearest
// photons are missing, as outside an edge) or |mean(u) - 1/2| sqrt(12 k) >= kPretestMean.
// On uniform discs 7-10 % of lookups pass (k = 10..500), and every one whose statistic
// passes the onset does, there and on half-plane profiles (edge_estimate_test.cpp; in
// simulations 1 in 8000 statistics above 9 failed the pretest, none above 10).
bool edgeWorthFitting(std::span<const double> u);

// The maximum likelihood edge for the ascending squared distances `sortedU` (each in
// [0, 1]): a grid over delta in (-sqrt(u_min), 1), refined by golden-section search. Fewer
// than kMinEdgePhotons give no edge. `scratch` is reused between calls.
EdgeFit maximiseEdgeLikelihood(std::span<const double> sortedU, std::vector<double>& scratch);

// (1 - w) + w lit(delta) / edgeDiscFraction(delta), with w the blend weight of EdgeParams
// and lit() the 0-to-1 ramp of half-width `blur` across delta = 0: the lit density times
// the lit fraction at the query over RADIANCE's whole-disc average.
double edgeFactor(const EdgeFit& fit, const EdgeParams& params = {});

// The edge correction of one lookup: `u` are the k photons' squared distances over the
// squared radius R^2 of the disc they were found in (each in [0, 1]; reordered). Pretest,
// fit and factor; factor 1 when the pretest fails.
EdgeFit fitEdge(std::span<double> u, std::vector<double>& scratch, const EdgeParams& params = {});

// A surface's own edge through the disc (-ape's own-surface estimate, density.h): the
// disc's part on the surface is x < delta, as the lit side above, with delta found from
// the covered fraction. Inverse of edgeDiscFraction for a fraction in [0, 1].
double edgeOffsetOfFraction(double fraction);

// Light often varies fastest right at a surface's edge (a slat lit on one side); the
// covered part's mean density then differs from the query's by the gradient times the
// part's centroid offset (0.42 radii for half a disc). Fitted here: photons spread over
// x < delta with density 1 + beta x (x across the edge in disc radii) have squared radii
// u distributed as a(u) + beta m(u), with a = edgeCircleFraction and m(u) = -sqrt(u)
// sin(theta0) / pi the circle's mean x (cos theta0 = delta / sqrt(u)). The maximum
// likelihood beta (Newton steps, kept where the density stays positive over the part)
// gives A / (A + beta Mx), A = edgeDiscFraction(delta) and Mx = -2/(3 pi) (1 - delta^2)^1.5
// the part's first moment over pi: the density at the query over the part's mean.
// Unbiased, and noisy: with the edge through the query the factor's spread is 20 % at
// k = 200 (10 % at a tenth of a radius inside, 5 % at 0.6), which a final gather
// averages away; gating it on significance was tried and left the bias on slats (a
// gradient of 60 % over one radius is significant in only some lookups at k = 200).
// `u` as fitEdge's (each in [0, 1]); `scratch` is reused between calls. Fewer than
// kMinEdgePhotons give 1.
double edgeGradientFactor(std::span<const double> u, double delta, std::vector<double>& scratch);

}  // namespace rp::pmap
