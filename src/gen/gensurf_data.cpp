// gensurf data files: reading and bilinear interpolation (see gensurf_data.h).
#include "gen/gensurf_data.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "util/error.h"

namespace rp::gen {

SurfaceData readSurfaceData(std::istream& in, const std::string& source, int m, int n,
                            bool triplets) {
    SurfaceData d;
    d.triplets = triplets;
    const int ps = triplets ? 3 : 1;
    const SourceLoc loc{source, 0};
    for (std::string word; in >> word;) {
        const char* s = word.c_str();
        char* end = nullptr;
        double v = std::strtod(s, &end);
        if (end == s || *end != '\0' || !std::isfinite(v))
            throw InputError(loc, "garbled data value '" + word + "'");
        d.values.push_back(v);
    }
    const size_t got = d.values.size();
    const size_t withBorder = size_t(m + 1) * size_t(n + 1) * ps;
    const size_t centres = size_t(m) * size_t(n) * ps;
    if (got == withBorder) {
        d.atVertices = true;
        d.ns = m + 1;
        d.nt = n + 1;
    } else if (got == centres && m >= 2 && n >= 2) {
        d.atVertices = false;
        d.ns = m;
        d.nt = n;
    } else {
        std::string want = std::to_string(withBorder);
        if (m >= 2 && n >= 2) want += " or " + std::to_string(centres);
        throw InputError(loc, "bad number of data points: expected " + want +
                                  (triplets ? " values (x y z triplets)" : " values") + ", got " +
                                  std::to_string(got));
    }
    return d;
}

double SurfaceData::value(int comp, double s, double t) const {
    // Grid coordinates: vertices sit at s*(ns-1); cell-centre data at s*ns - 1/2.
    double u = atVertices ? s * (ns - 1) : s * ns - 0.5;
    double v = atVertices ? t * (nt - 1) : t * nt - 0.5;
    // RADIANCE compat (gensurf.c l_dataval): truncation toward zero, then clamping to
    // the end cells, so points outside extrapolate from those cells.
    int i = std::clamp(static_cast<int>(u), 0, ns - 2);
    int j = std::clamp(static_cast<int>(v), 0, nt - 2);
    const int ps = triplets ? 3 : 1;
    auto at = [&](int ii, int jj) { return values[size_t(ps) * (size_t(jj) * ns + ii) + comp]; };
    double d00 = at(i, j), d01 = at(i + 1, j), d10 = at(i, j + 1), d11 = at(i + 1, j + 1);
    return (j + 1 - v) * ((i + 1 - u) * d00 + (u - i) * d01) +
           (v - j) * ((i + 1 - u) * d10 + (u - i) * d11);
}

}  // namespace rp::gen
