// Tensor-tree internals shared by the tree's reader (tensor_tree_data.cpp: the tree,
// its ScatteringData parser, the Shirley-Chiu and Hilbert mappings) and its scattering
// distribution (tensor_tree.cpp). See tensor_tree.cpp for the format.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "bsdf/xml_detail.h"

namespace rp::bsdf::detail::ttree {

constexpr double kTiny = 1e-6;                  // RADIANCE FTINY
constexpr double kMapShrink = 0.9999999999999;  // disk2square.c's guard factor
constexpr int kHilbertBits = 16;                // output cells are located on a 2^16 grid
constexpr double kHilbertScale = 65536.0;
constexpr double kCumlMax = 4294967295.0;  // cumulative values are 32-bit, as RADIANCE's
constexpr double kBelowOne = 1 - 0x1p-53;  // largest double below 1

// RADIANCE's sidef: which way the tree scatters (the sampled direction's side follows).
enum class Side : uint8_t { ReflFront, ReflBack, XmitFront, XmitBack };

// Shirley-Chiu: unit disk -> unit square, and back (RADIANCE's disk2square.c mapping).
void diskToSquare(double dx, double dy, double sq[2]);
void squareToDisk(double u, double v, double& dx, double& dy);
// Rotation about +Z by theta (RADIANCE spinvector with the Z axis).
Vec3 spinZ(const Vec3& v, double theta);
// Hilbert curve on a 2^16 x 2^16 grid (see tensor_tree_data.cpp).
uint32_t hilbertIndex(uint32_t x, uint32_t y);
void hilbertPoint(uint32_t d, uint32_t& x, uint32_t& y);

// ---------------------------------------------------------------------------------
// The tree: nodes in one array (a branch's 2^ndim children are contiguous), leaf grids
// in one value array. A grid of log2 resolution k holds 2^(ndim k) values, dimension 0
// most significant; a branch's child n covers the upper half of dimension i where bit
// i of n is set (RADIANCE's layout).
struct Node {
    int32_t log2GR;  // < 0: branch
    uint32_t index;  // first child (branch) or first value (grid)
};

struct Tree {
    int ndim = 4;
    std::vector<Node> nodes;
    std::vector<float> values;

    // The leaf value at pos (each coordinate in [0,1)) and the leaf's width.
    float lookup(const double pos[4], double& width) const;
    // Calls f(value, cellMin[4], cellSize) for every leaf cell containing pos in the
    // dimensions of `fixedMask`.
    template <class F>
    void traverse(const double pos[4], unsigned fixedMask, F&& f) const {
        const double cmin[4] = {0, 0, 0, 0};
        visit(0, cmin, 1.0, pos, fixedMask, f);
    }
    template <class F>
    void visit(uint32_t n, const double cmin[4], double csiz, const double pos[4],
               unsigned fixedMask, F& f) const;
    template <class F>
    void visitGrid(const Node& nd, const double cmin[4], double csiz, const double pos[4],
                   unsigned fixedMask, F& f) const;

    double smallestLeaf(uint32_t n = 0) const;
    double boxAverage(uint32_t n, const double bmin[4], const double bmax[4]) const;
    float minimum(uint32_t n) const;
    float liveMinimum() const;
};

// Calls f(ix, idx) for every cell ix of a leaf grid (log2 resolution k) with
// lo[i] <= ix[i] < hi[i] in each of the ndim dimensions; idx is its place in the grid's
// values (dimension 0 most significant).
template <class F>
void forEachGridCell(int ndim, int k, const int lo[4], const int hi[4], F&& f) {
    int l[4] = {0, 0, 0, 0}, h[4] = {1, 1, 1, 1};
    for (int i = 0; i < ndim; ++i) l[i] = lo[i], h[i] = hi[i];
    for (int a = l[0]; a < h[0]; ++a)
        for (int b = l[1]; b < h[1]; ++b)
            for (int c = l[2]; c < h[2]; ++c)
                for (int d = l[3]; d < h[3]; ++d) {
                    const int ix[4] = {a, b, c, d};
                    size_t idx = 0;
                    for (int i = 0; i < ndim; ++i) idx = (idx << k) | static_cast<size_t>(ix[i]);
                    f(ix, idx);
                }
}

template <class F>
void Tree::visit(uint32_t n, const double cmin[4], double csiz, const double pos[4],
                 unsigned fixedMask, F& f) const {
    const Node& nd = nodes[n];
    if (nd.log2GR >= 0) {
        visitGrid(nd, cmin, csiz, pos, fixedMask, f);
        return;
    }
    const double half = csiz * .5;
    for (unsigned child = 0; child < (1u << ndim); ++child) {
        double sub[4];
        bool keep = true;
        for (int i = 0; i < ndim; ++i) {
            const bool upper = child >> i & 1;
            sub[i] = cmin[i] + (upper ? half : 0);
            if (fixedMask >> i & 1 && upper != (pos[i] >= cmin[i] + half)) keep = false;
        }
        if (keep) visit(nd.index + child, sub, half, pos, fixedMask, f);
    }
}

template <class F>
void Tree::visitGrid(const Node& nd, const double cmin[4], double csiz, const double pos[4],
                     unsigned fixedMask, F& f) const {
    const int k = nd.log2GR;
    const int res = 1 << k;
    const double cw = csiz / res;
    int lo[4], hi[4];
    for (int i = 0; i < ndim; ++i) {
        if (fixedMask >> i & 1) {
            lo[i] = std::clamp(static_cast<int>((pos[i] - cmin[i]) / cw), 0, res - 1);
            hi[i] = lo[i] + 1;
        } else {
            lo[i] = 0;
            hi[i] = res;
        }
    }
    double cell[4] = {0, 0, 0, 0};
    forEachGridCell(ndim, k, lo, hi, [&](const int ix[4], size_t idx) {
        for (int i = 0; i < ndim; ++i) cell[i] = cmin[i] + cw * ix[i];
        f(values[nd.index + idx], cell, cw);
    });
}

// The tree of one WavelengthDataBlock (its AngleBasis checked), errors at the XML's lines.
Tree parseScatteringData(const pugi::xml_node& block, int ndim, const XmlContext& ctx);

}  // namespace rp::bsdf::detail::ttree
