// gensurf(1): parametric surfaces (see gensurf.h). Matches RADIANCE gensurf.c (2.12):
// cell orientation and diagonals, polygon numbering, the -s Phong fit, the -o .OBJ text.
#include "gen/gensurf.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <utility>

#include "gen/gen_text.h"
#include "util/error.h"

namespace rp::gen {

namespace {

// RADIANCE's FTINY, squared as gensurf.c uses it (planarity and zero-vector tests).
constexpr double kFtiny = 1e-6;

const char* kUsage =
    "usage: gensurf mat name 'x(s,t)' 'y(s,t)' 'z(s,t)' m n [-e expr][-f file][-s][-o]";

bool zeroVector(const Vec3& v) { return dot(v, v) <= kFtiny * kFtiny; }

std::string vertexText(const Vec3& p) {
    return cformat("%18.12g %18.12g %18.12g\n", p.x, p.y, p.z);
}

// One grid cell ready for output: its corners in putsquare() order (p0 p1 p2 p3, with
// the triangles p0 p1 p2 and p2 p1 p3), which triangles exist, their unit normals, and
// whether they merge into the quad p0 p1 p3 p2.
struct Cell {
    const SurfPoint* p[4];
    int i[4], j[4];  // grid coordinates of p[k]
    bool ok1 = false, ok2 = false, quad = false;
    Vec3 vc1, vc2;
};

// RADIANCE compat (gensurf.c main loop): even columns j split along (i,j)-(i+1,j+1), odd
// ones along (i+1,j)-(i,j+1), unless an invalid corner forces the diagonal that keeps the
// remaining triangle.
std::optional<Cell> makeCell(const SurfGrid& g, int i, int j) {
    bool orient = (j & 1) != 0;
    if (!(g.at(i, j).valid && g.at(i + 1, j + 1).valid))
        orient = true;
    else if (!(g.at(i + 1, j).valid && g.at(i, j + 1).valid))
        orient = false;
    Cell cell;
    // Corner order: (i,j) (i+1,j) (i,j+1) (i+1,j+1) when orient, else
    // (i+1,j) (i+1,j+1) (i,j) (i,j+1); either way p1-p0 x p2-p0 follows ds x dt.
    const int di[4] = {0, 1, 0, 1}, dj[4] = {0, 0, 1, 1};
    const int order[4] = {orient ? 0 : 1, orient ? 1 : 3, orient ? 2 : 0, orient ? 3 : 2};
    for (int k = 0; k < 4; ++k) {
        cell.i[k] = i + di[order[k]];
        cell.j[k] = j + dj[order[k]];
        cell.p[k] = &g.at(cell.i[k], cell.j[k]);
    }
    const SurfPoint &p0 = *cell.p[0], &p1 = *cell.p[1], &p2 = *cell.p[2], &p3 = *cell.p[3];
    if (p0.valid && p1.valid && p2.valid) {
        cell.vc1 = cross(p1.p - p0.p, p2.p - p0.p);
        cell.ok1 = length(cell.vc1) > 0;
        cell.vc1 = normalize(cell.vc1);
    }
    if (p1.valid && p2.valid && p3.valid) {
        cell.vc2 = cross(p2.p - p3.p, p1.p - p3.p);
        cell.ok2 = length(cell.vc2) > 0;
        cell.vc2 = normalize(cell.vc2);
    }
    if (!cell.ok1 && !cell.ok2) return std::nullopt;
    cell.quad = cell.ok1 && cell.ok2 && dot(cell.vc1, cell.vc2) >= 1.0 - kFtiny * kFtiny;
    return cell;
}

// Inverts a 4x4 matrix by Gauss-Jordan elimination with partial pivoting; false when
// singular (a pivot below 1e-12 of the largest entry: our threshold).
bool invert4(double a[4][4], double inv[4][4]) {
    double big = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            big = std::fmax(big, std::fabs(a[r][c]));
            inv[r][c] = r == c ? 1 : 0;
        }
    if (big == 0) return false;
    for (int col = 0; col < 4; ++col) {
        int piv = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::fabs(a[r][col]) > std::fabs(a[piv][col])) piv = r;
        if (std::fabs(a[piv][col]) <= 1e-12 * big) return false;
        for (int c = 0; c < 4; ++c) {
            std::swap(a[col][c], a[piv][c]);
            std::swap(inv[col][c], inv[piv][c]);
        }
        double d = a[col][col];
        for (int c = 0; c < 4; ++c) {
            a[col][c] /= d;
            inv[col][c] /= d;
        }
        for (int r = 0; r < 4; ++r) {
            if (r == col || a[r][col] == 0) continue;
            double f = a[r][col];
            for (int c = 0; c < 4; ++c) {
                a[r][c] -= f * a[col][c];
                inv[r][c] -= f * inv[col][c];
            }
        }
    }
    return true;
}

// gensurf -s: fits n(u,v) = A*u*v + B*u + C*v + D through the four corner normals, with
// (u, v) the two coordinates other than the dominant axis of the summed normals. False
// when the corners do not determine the fit (e.g. collinear in the (u, v) projection).
bool phongFit(const Cell& cell, int& axis, Vec3 coef[4]) {
    Vec3 sum;
    for (const SurfPoint* p : cell.p) sum += p->normal;
    axis = std::fabs(sum.x) > std::fabs(sum.y) ? 0 : 1;
    axis = std::fabs(sum[axis]) > std::fabs(sum.z) ? axis : 2;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    double a[4][4], inv[4][4];
    for (int k = 0; k < 4; ++k) {
        const Vec3& p = cell.p[k]->p;
        a[k][0] = p[u] * p[v];
        a[k][1] = p[u];
        a[k][2] = p[v];
        a[k][3] = 1;
    }
    if (!invert4(a, inv)) return false;
    for (int row = 0; row < 4; ++row) {
        coef[row] = Vec3();
        for (int k = 0; k < 4; ++k) coef[row] += inv[row][k] * cell.p[k]->normal;
    }
    return true;
}

}  // namespace

GensurfOptions parseGensurfArgs(const std::vector<std::string>& args) {
    if (args.size() < 8) throw InputError(kUsage);
    GensurfOptions opt;
    opt.material = args[1];
    opt.name = args[2];
    opt.xExpr = args[3];
    opt.yExpr = args[4];
    opt.zExpr = args[5];
    opt.m = parseInt(args[6], "m");
    opt.n = parseInt(args[7], "n");
    if (opt.m <= 0) throw InputError("m must be positive, got " + std::to_string(opt.m));
    if (opt.n <= 0) throw InputError("n must be positive, got " + std::to_string(opt.n));
    OptionTable table = genOptionTable();
    table.add(wordOption("-s", [&opt] { opt.smooth = true; }));
    table.add(wordOption("-o", [&opt] { opt.obj = true; }));
    addCalcOptions(table, opt.sources);
    std::vector<std::string> words = args;
    table.parseAll(words, 8);
    if (opt.zExpr == "-" || std::ifstream(opt.zExpr).good())
        opt.data = opt.xExpr == opt.zExpr && opt.yExpr == opt.zExpr ? GensurfOptions::Data::Points
                                                                    : GensurfOptions::Data::Z;
    return opt;
}

SurfGrid sampleSurface(const GensurfOptions& opt, GenFunctions& funcs, const SurfaceData* data) {
    using Data = GensurfOptions::Data;
    RP_CHECK(opt.data == Data::None || data != nullptr);
    GenFunctionId xf, yf, zf, validf;
    if (opt.data != Data::Points) {
        xf = funcs.define("x(s,t)", "s, t", opt.xExpr);
        yf = funcs.define("y(s,t)", "s, t", opt.yExpr);
    }
    if (opt.data == Data::None) zf = funcs.define("z(s,t)", "s, t", opt.zExpr);
    funcs.build();
    const bool checkValid = funcs.userFunction("valid", 2, validf);

    SurfGrid g(opt.m, opt.n);
    const int lo = opt.smooth ? -1 : 0;  // -s samples one step past every edge
    for (int i = lo; i <= opt.m - lo; ++i)
        for (int j = lo; j <= opt.n - lo; ++j) {
            SurfPoint& pt = g.at(i, j);
            const double s = double(i) / opt.m, t = double(j) / opt.n;
            if (checkValid && funcs.call(validf, s, t) <= 0) continue;  // stays invalid
            pt.valid = true;
            pt.s = s;
            pt.t = t;
            if (opt.data == Data::Points) {
                pt.p = Vec3(data->value(0, s, t), data->value(1, s, t), data->value(2, s, t));
            } else {
                pt.p.x = funcs.call(xf, s, t);
                pt.p.y = funcs.call(yf, s, t);
                pt.p.z = opt.data == Data::Z ? data->value(0, s, t) : funcs.call(zf, s, t);
            }
        }
    if (!opt.smooth) return g;
    // Normals at i = 0..m, j = 0..n from the neighbours (gensurf.c compnorms). Unlike
    // RADIANCE, whose loop stops advancing after an invalid sample, every point gets its
    // own normal.
    for (int i = 0; i <= opt.m; ++i)
        for (int j = 0; j <= opt.n; ++j) {
            SurfPoint& pt = g.at(i, j);
            if (!pt.valid) continue;
            const SurfPoint &sm = g.at(i - 1, j), &sp = g.at(i + 1, j);
            const SurfPoint &tm = g.at(i, j - 1), &tp = g.at(i, j + 1);
            if ((!sm.valid && !sp.valid) || (!tm.valid && !tp.valid)) continue;  // no normal
            Vec3 ds = !sm.valid ? sp.p - pt.p : !sp.valid ? pt.p - sm.p : sp.p - sm.p;
            Vec3 dt = !tm.valid ? tp.p - pt.p : !tp.valid ? pt.p - tm.p : tp.p - tm.p;
            pt.normal = normalize(cross(ds, dt));
        }
    return g;
}

std::vector<SurfPolygon> gensurfPolygons(const GensurfOptions& opt, const SurfGrid& grid) {
    std::vector<SurfPolygon> out;
    auto add = [&](std::vector<Vec3> verts, bool phong, int axis, const Vec3 coef[4],
                   const Vec3& faceNormal) {
        SurfPolygon p;
        p.name = opt.name + "." + std::to_string(out.size() + 1);
        p.vertices = std::move(verts);
        p.phong = phong;
        if (phong) {
            p.axis = axis;
            for (int k = 0; k < 4; ++k) p.coef[k] = coef[k];
            p.coef[3] -= faceNormal;
        }
        out.push_back(std::move(p));
    };
    for (int i = 0; i < grid.m(); ++i)
        for (int j = 0; j < grid.n(); ++j) {
            std::optional<Cell> c = makeCell(grid, i, j);
            if (!c) continue;
            int axis = 0;
            Vec3 coef[4];
            const bool phong = opt.smooth && phongFit(*c, axis, coef);
            const Vec3 &p0 = c->p[0]->p, &p1 = c->p[1]->p, &p2 = c->p[2]->p, &p3 = c->p[3]->p;
            if (c->quad) {
                add({p0, p1, p3, p2}, phong, axis, coef, (c->vc1 + c->vc2) * 0.5);
                continue;
            }
            if (c->ok1) add({p0, p1, p2}, phong, axis, coef, c->vc1);
            if (c->ok2) add({p2, p1, p3}, phong, axis, coef, c->vc2);
        }
    return out;
}

std::string formatSurfPolygon(const std::string& material, const SurfPolygon& p) {
    std::string out = "\n" + material + " ";
    if (p.phong) {
        out += "texfunc Phong\n4 surf_dx surf_dy surf_dz surf.cal\n0\n";
        out += cformat("13\t%d\n", p.axis);
        for (const Vec3& c : p.coef) out += vertexText(c);
        out += "\nPhong ";
    }
    out += "polygon " + p.name + "\n0\n0\n" + std::to_string(3 * p.vertices.size()) + "\n";
    for (const Vec3& v : p.vertices) out += vertexText(v);
    return out;
}

std::string gensurfObj(const GensurfOptions& opt, const SurfGrid& grid) {
    // RADIANCE compat (gensurf.c 2.29): faces refer to vertices and normals by relative
    // (negative) numbers, 0 = none; a normal equal to the last one written (each
    // component within 1e-6) is not written again but shared.
    const int m = grid.m(), n = grid.n();
    std::vector<int> vnum(size_t(m + 1) * size_t(n + 1), 0), nnum(vnum.size(), 0);
    int nv = 0, nn = 0;
    Vec3 lastNormal;
    auto same = [](const Vec3& a, const Vec3& b) {
        return std::fabs(a.x - b.x) <= 1e-6 && std::fabs(a.y - b.y) <= 1e-6 &&
               std::fabs(a.z - b.z) <= 1e-6;
    };
    auto putRow = [&](int i) {
        std::string s;
        for (int j = 0; j <= n; ++j) {
            const SurfPoint& p = grid.at(i, j);
            if (!p.valid) continue;
            size_t x = size_t(i) * size_t(n + 1) + size_t(j);
            s += "v " + vertexText(p.p);
            vnum[x] = ++nv;
            s += cformat("\tvt %.9g %.9g\n", p.s, p.t);
            if (!opt.smooth || zeroVector(p.normal)) continue;
            if (same(p.normal, lastNormal)) {
                nnum[x] = nn;
                continue;
            }
            s += cformat("\tvn %.9g %.9g %.9g\n", p.normal.x, p.normal.y, p.normal.z);
            nnum[x] = ++nn;
            lastNormal = p.normal;
        }
        return s;
    };
    std::string out = "\nusemtl " + opt.material + "\n\no " + opt.name + "\n\n" + putRow(0);
    for (int i = 0; i < m; ++i) {
        out += putRow(i + 1);
        for (int j = 0; j < n; ++j) {
            std::optional<Cell> c = makeCell(grid, i, j);
            if (!c) continue;
            auto ref = [&](int k) {
                size_t x = size_t(c->i[k]) * size_t(n + 1) + size_t(c->j[k]);
                int v = vnum[x] ? vnum[x] - nv - 1 : 0, nr = nnum[x] ? nnum[x] - nn - 1 : 0;
                return cformat(" %d/%d/%d", v, v, nr);
            };
            if (c->quad) {
                out += "f" + ref(0) + ref(1) + ref(3) + ref(2) + "\n";
                continue;
            }
            if (c->ok1) out += "f" + ref(0) + ref(1) + ref(2) + "\n";
            if (c->ok2) out += "f" + ref(2) + ref(1) + ref(3) + "\n";
        }
    }
    return out;
}

std::string gensurf(const std::vector<std::string>& args,
                    const std::vector<std::string>& searchPath, std::istream& stdIn,
                    std::vector<std::string>& warnings) {
    GensurfOptions opt = parseGensurfArgs(args);
    GenFunctions funcs(opt.sources, searchPath);
    std::optional<SurfaceData> data;
    if (opt.data != GensurfOptions::Data::None) {
        const bool triplets = opt.data == GensurfOptions::Data::Points;
        if (opt.zExpr == "-") {
            data = readSurfaceData(stdIn, "<stdin>", opt.m, opt.n, triplets);
        } else {
            std::ifstream in(opt.zExpr);
            if (!in) throw InputError(SourceLoc{opt.zExpr, 0}, "cannot open");
            data = readSurfaceData(in, opt.zExpr, opt.m, opt.n, triplets);
        }
    }
    SurfGrid grid = sampleSurface(opt, funcs, data ? &*data : nullptr);
    std::string out = commandHeader(args);
    if (opt.obj) {
        out += gensurfObj(opt, grid);
    } else {
        for (const SurfPolygon& p : gensurfPolygons(opt, grid))
            out += formatSurfPolygon(opt.material, p);
    }
    if (std::string w = funcs.mathWarning(); !w.empty()) warnings.push_back(w);
    return out;
}

}  // namespace rp::gen
