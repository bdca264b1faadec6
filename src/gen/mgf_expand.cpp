// MGF entities that RADIANCE's parser rewrites before mgf2rad sees them: faces with holes
// (one face whose outline runs into each hole and back), prisms (faces) and tori (cones).
// The rewritten entities are the ones RADIANCE's parser makes, down to the vertex names
// and the %.12g text of every computed point, so the output agrees digit for digit.
#include <cmath>
#include <cstdlib>

#include "gen/gen_text.h"
#include "gen/mgf_reader.h"

namespace rp::gen {

namespace {

std::string g12(double v) { return cformat("%.12g", v); }

MgfArgs pointEntity(const Vec3& p) { return {"p", g12(p.x), g12(p.y), g12(p.z)}; }

}  // namespace

void MgfReader::faceWithHoles(const MgfArgs& av) {
    // "fh v1 v2 v3 ... - h1 h2 h3 ... - ...": each hole is entered from the last outline
    // vertex seen, walked round, and left back to that vertex.
    size_t ac = av.size();
    MgfArgs out(ac + 1);
    out[0] = "f";
    size_t lastOutline = 0, i = 1;
    for (; i < ac; ++i) {
        if (av[i][0] != '-') {
            out[i] = av[i];
            continue;
        }
        if (i < 4) mgfFail(MgfError::ArgCount);
        if (i >= ac - 1) break;
        if (!lastOutline) lastOutline = i - 1;
        size_t j = i + 1;
        while (j < ac - 1 && av[j + 1][0] != '-') ++j;
        if (j - i < 3) mgfFail(MgfError::ArgCount);
        out[i] = av[j];  // the hole's last vertex closes its loop
    }
    if (lastOutline) out[i++] = av[lastOutline];
    out.resize(i);
    handle(out);
}

void MgfReader::prism(const MgfArgs& av) {
    size_t ac = av.size();
    if (ac < 5) mgfFail(MgfError::ArgCount);
    if (!mgfIsFloat(av[ac - 1])) mgfFail(MgfError::ArgType);
    double len = std::atof(av[ac - 1].c_str());
    if (len <= 1e-6 && len >= -1e-6) mgfFail(MgfError::IllegalValue);
    // The base's normal (Newell's sum about the first vertex): the prism extends along -n.
    const MgfVertex* v0 = vertex(av[1]);
    if (!v0) mgfFail(MgfError::Undefined);
    bool hasNormals = false;
    Vec3 n, prev;
    for (size_t i = 2; i < ac - 1; ++i) {
        const MgfVertex* v = vertex(av[i]);
        if (!v) mgfFail(MgfError::Undefined);
        hasNormals |= dot(v->n, v->n) > 1e-12;
        Vec3 d = v->p - v0->p;
        n += cross(prev, d);
        prev = d;
    }
    if (mgfNormalize(n) == 0) mgfFail(MgfError::IllegalValue);
    size_t nv = ac - 2;
    std::vector<std::string> moved(nv);
    for (size_t i = 1; i <= nv; ++i) {
        moved[i - 1] = "_pv" + std::to_string(i);
        handle({"v", moved[i - 1], "=", av[i]});
        handle(pointEntity(vertex(av[i])->p - len * n));
    }
    // Sides: each base edge with its moved copy.
    for (size_t i = 1; i <= nv; ++i) {
        size_t k = i == 1 ? nv : i - 1;
        handle({"f", moved[i - 1], av[i], av[k], moved[k - 1]});
    }
    // The moved end, reversed; normals dropped so that the ends stay flat.
    MgfArgs top{"f"};
    for (size_t i = nv; i >= 1; --i) {
        if (hasNormals) {
            handle({"v", moved[i - 1]});
            handle({"n", "0", "0", "0"});
        }
        top.push_back(moved[i - 1]);
    }
    handle(top);
    MgfArgs bottom{"f"};
    for (size_t i = 1; i <= nv; ++i) {
        if (hasNormals) {
            handle({"v", moved[i - 1], "=", av[i]});
            handle({"n", "0", "0", "0"});
            bottom.push_back(moved[i - 1]);
        } else {
            bottom.push_back(av[i]);
        }
    }
    handle(bottom);
}

void MgfReader::torus(const MgfArgs& av) {
    if (av.size() != 4) mgfFail(MgfError::ArgCount);
    const MgfVertex* cv = vertex(av[1]);
    if (!cv) mgfFail(MgfError::Undefined);
    if (dot(cv->n, cv->n) <= 1e-12) mgfFail(MgfError::IllegalValue);
    if (!mgfIsFloat(av[2]) || !mgfIsFloat(av[3])) mgfFail(MgfError::ArgType);
    const MgfVertex centre = *cv;  // the vertices below are redefined as we go
    double minRad = std::atof(av[2].c_str()), maxRad = std::atof(av[3].c_str());
    if (minRad <= 1e-6 && minRad >= -1e-6) minRad = 0;
    double sgn = minRad > 0 ? 1 : minRad < 0 ? -1 : maxRad > 0 ? 1 : maxRad < 0 ? -1 : 0;
    if (sgn == 0 || sgn * (maxRad - minRad) <= 0) mgfFail(MgfError::IllegalValue);
    const int quarter = 5;  // RADIANCE's MG_NQCD divisions per quarter circle
    double half = .5 * (maxRad - minRad), avgRad = .5 * (minRad + maxRad);
    auto ringPoint = [&](double theta) {
        return centre.p + sgn * half * std::cos(theta) * centre.n;
    };
    handle({"v", "_tv2", "=", av[1]});
    handle(pointEntity(ringPoint(0)));
    // Outer half of the tube as cones, then the inner half (negative radii: inward).
    std::string r1, r2 = g12(avgRad);
    for (int i = 1; i <= 4 * quarter; ++i) {
        double theta = i * (kPi / 2) / quarter;
        if (i == 2 * quarter + 1) r2 = g12(-avgRad);
        handle({"v", "_tv1", "=", "_tv2"});
        handle({"v", "_tv2"});
        handle(pointEntity(ringPoint(theta)));
        r1 = r2;
        r2 = i <= 2 * quarter ? g12(avgRad + half * std::sin(theta))
                              : g12(-avgRad - half * std::sin(theta));
        handle({"cone", "_tv1", r1, "_tv2", r2});
    }
}

}  // namespace rp::gen
