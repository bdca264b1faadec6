// gensurf(1): a parametric surface (x(s,t), y(s,t), z(s,t)), s and t = 0..1 in m and n
// steps, as quadrilaterals (or triangles where a cell is not planar), optionally smoothed
// (-s) with Phong texfuncs, or written as Wavefront .OBJ (-o). Command parsing, sampling,
// tessellation and RADIANCE's text layout; data files are gensurf_data.h, expressions
// gen_func.h, the tool main tools/gensurf.cpp.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "gen/gen_func.h"
#include "gen/gensurf_data.h"
#include "util/vec.h"

namespace rp::gen {

struct GensurfOptions {
    std::string material;
    std::string name;
    std::string xExpr, yExpr, zExpr;  // x(s,t) y(s,t) z(s,t), or data file names
    int m = 0, n = 0;                 // steps in s and t, > 0
    std::vector<CalcSource> sources;  // -e / -f in order
    bool smooth = false;              // -s
    bool obj = false;                 // -o
    // RADIANCE compat (gensurf.c main): the z argument names a data file when it is "-"
    // (standard input) or a readable file; z values only, or x y z triplets when the x
    // and y arguments name the same file.
    enum class Data { None, Z, Points };
    Data data = Data::None;
};

// Parses gensurf's command line; args[0] is the program name. Throws InputError for a
// wrong argument count, non-integer or non-positive m or n, or an unknown option.
GensurfOptions parseGensurfArgs(const std::vector<std::string>& args);

// One sample: position, averaged unit normal (-s only; zero when undefined), (s, t).
struct SurfPoint {
    bool valid = false;  // false where valid(s,t) <= 0, or outside the sampled range
    Vec3 p;
    Vec3 normal;
    double s = 0, t = 0;
};

// Samples at s = i/m, t = j/n for i = 0..m, j = 0..n; with -s also one step beyond each
// edge (i = -1, m+1; j = -1, n+1), which the normals at the edges use.
class SurfGrid {
public:
    SurfGrid(int m, int n) : m_(m), n_(n), pts_(size_t(m + 3) * size_t(n + 3)) {}
    int m() const { return m_; }
    int n() const { return n_; }
    SurfPoint& at(int i, int j) { return pts_[size_t(i + 1) * size_t(n_ + 3) + size_t(j + 1)]; }
    const SurfPoint& at(int i, int j) const {
        return pts_[size_t(i + 1) * size_t(n_ + 3) + size_t(j + 1)];
    }

private:
    int m_, n_;
    std::vector<SurfPoint> pts_;
};

// Evaluates the surface (and valid(s,t) when the user defined it with two parameters)
// and, with -s, the vertex normals: the normalised cross product of the central
// differences along s and t (one-sided next to invalid samples), so the normal follows
// the right-hand rule on (s, t). `data` is used for the data-file forms.
SurfGrid sampleSurface(const GensurfOptions& opt, GenFunctions& funcs, const SurfaceData* data);

// One output polygon. Vertices run counter-clockwise about the (s, t) right-hand normal.
struct SurfPolygon {
    std::string name;            // "name.<k>", k counting every polygon from 1
    std::vector<Vec3> vertices;  // 4 (planar cell) or 3 (half of a non-planar cell)
    // -s: the Phong texfunc's 13 real arguments: the dominant normal axis, then the
    // bilinear normal fit a*u*v + b*u + c*v + d over the other two coordinates (u, v),
    // with the polygon's own normal subtracted from d (surf.cal adds the perturbation).
    bool phong = false;
    int axis = 0;
    Vec3 coef[4];
};

// The polygons in RADIANCE gensurf's order: cells row by row in s, then t; a cell whose
// two triangles agree in normal (cosine >= 1 - 1e-12) is one quad, else two triangles
// split along alternating diagonals; degenerate or invalid triangles are left out.
std::vector<SurfPolygon> gensurfPolygons(const GensurfOptions& opt, const SurfGrid& grid);

// One polygon as gensurf prints it ("\n" first; "%18.12g %18.12g %18.12g" vertex lines).
std::string formatSurfPolygon(const std::string& material, const SurfPolygon& p);

// -o: the surface as Wavefront .OBJ text (usemtl, o, v/vt/vn per valid vertex, f records
// with relative vertex numbers).
std::string gensurfObj(const GensurfOptions& opt, const SurfGrid& grid);

// The whole output: "# gensurf ..." header then the polygons (or the .OBJ text).
// `searchPath` is where -f files are found, `stdIn` is read for a "-" data file;
// `warnings` receives the math-error warning, if any.
std::string gensurf(const std::vector<std::string>& args,
                    const std::vector<std::string>& searchPath, std::istream& stdIn,
                    std::vector<std::string>& warnings);

}  // namespace rp::gen
