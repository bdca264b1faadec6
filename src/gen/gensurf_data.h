// gensurf's recorded data (the "dfile" invocation forms of gensurf(1)): z values or x y z
// triplets on an m x n (cell centres) or (m+1) x (n+1) (vertices) grid, s varying
// fastest, and their bilinear interpolation. Command parsing and tessellation live in
// gensurf.h.
#pragma once

#include <istream>
#include <string>
#include <vector>

namespace rp::gen {

struct SurfaceData {
    bool triplets = false;   // x y z per point, else z only
    bool atVertices = true;  // (m+1)*(n+1) values; false: m*n values at cell centres
    int ns = 0, nt = 0;      // points along s and along t (both >= 2)
    std::vector<double> values;

    // Component `comp` (0..2 = x y z for triplets; 0 for z-only data) at (s, t), by
    // bilinear interpolation in the cell around it; beyond the grid the end cells are
    // extended linearly (gensurf -s samples one step past the edges).
    double value(int comp, double s, double t) const;
};

// Reads the values of a data file for an m x n surface. `source` names the input in
// errors ("<stdin>" for standard input). Throws InputError for a word that is not a
// number, or a count that is neither (m+1)*(n+1) nor m*n points (m*n needs m, n >= 2).
SurfaceData readSurfaceData(std::istream& in, const std::string& source, int m, int n,
                            bool triplets);

}  // namespace rp::gen
