// The tensor tree's storage, its ScatteringData parser and the mappings it is indexed by
// (see tensor_tree.h).
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "bsdf/multi_sample.h"
#include "bsdf/tensor_tree.h"

namespace rp::bsdf::detail::ttree {

// Shirley-Chiu: unit disk -> unit square (inverse of squareToDisk), with RADIANCE's
// tiny scale factor so that cells are assigned exactly as RADIANCE assigns them.
void diskToSquare(double dx, double dy, double sq[2]) {
    const double r = std::sqrt(dx * dx + dy * dy);
    double phi = std::atan2(dy, dx);
    if (phi < -kPi / 4) phi += 2 * kPi;  // [-pi/4, 7pi/4)
    double a, b;
    if (phi < kPi / 4) {
        a = r;
        b = phi * a / (kPi / 4);
    } else if (phi < 3 * kPi / 4) {
        b = r;
        a = -(phi - kPi / 2) * b / (kPi / 4);
    } else if (phi < 5 * kPi / 4) {
        a = -r;
        b = (phi - kPi) * a / (kPi / 4);
    } else {
        b = -r;
        a = -(phi - 3 * kPi / 2) * b / (kPi / 4);
    }
    sq[0] = a * (0.5 / kMapShrink) + 0.5;
    sq[1] = b * (0.5 / kMapShrink) + 0.5;
}

// Shirley-Chiu: unit square -> unit disk, area-preserving (so uniform square samples
// are cosine-distributed directions).
void squareToDisk(double u, double v, double& dx, double& dy) {
    const double a = 2 * u - 1, b = 2 * v - 1;
    double r, phi;
    if (a > -b) {
        if (a > b) {
            r = a;
            phi = (kPi / 4) * (b / a);
        } else {
            r = b;
            phi = (kPi / 4) * (2 - a / b);
        }
    } else {
        if (a < b) {
            r = -a;
            phi = (kPi / 4) * (4 + b / a);
        } else {
            r = -b;
            phi = b != 0 ? (kPi / 4) * (6 - a / b) : 0;
        }
    }
    r *= kMapShrink;
    dx = r * std::cos(phi);
    dy = r * std::sin(phi);
}

// Rotation about +Z by theta (RADIANCE spinvector with the Z axis).
Vec3 spinZ(const Vec3& v, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    return {v.x * c - v.y * s, v.x * s + v.y * c, v.z};
}

// Hilbert curve on a 2^16 x 2^16 grid. Every aligned 2^k square is one contiguous run
// of 4^k indices, so sorting output cells by index orders them along the curve (nearby
// random numbers give nearby directions) and a cell's run starts at its first index.
uint32_t hilbertIndex(uint32_t x, uint32_t y) {
    uint32_t d = 0;
    for (uint32_t s = 1u << (kHilbertBits - 1); s > 0; s >>= 1) {
        const uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
        d += s * s * ((3 * rx) ^ ry);
        if (ry == 0) {  // rotate the quadrant so the sub-curve starts where it enters
            if (rx == 1) {
                x = ~x;
                y = ~y;
            }
            std::swap(x, y);
        }
    }
    return d;
}

void hilbertPoint(uint32_t d, uint32_t& x, uint32_t& y) {
    uint64_t a, b;
    bsdf::hilbertPoint(kHilbertBits, d, a, b);
    x = static_cast<uint32_t>(a);
    y = static_cast<uint32_t>(b);
}

float Tree::lookup(const double pos[4], double& width) const {
    double p[4];
    for (int i = 0; i < ndim; ++i) p[i] = std::clamp(pos[i], 0.0, kBelowOne);
    double w = 1;
    const Node* nd = &nodes[0];
    while (nd->log2GR < 0) {
        unsigned child = 0;
        for (int i = 0; i < ndim; ++i) {
            p[i] *= 2;
            if (p[i] >= 1) {
                p[i] -= 1;
                child |= 1u << i;
            }
        }
        w *= .5;
        nd = &nodes[nd->index + child];
    }
    const int k = nd->log2GR;
    const uint32_t res = 1u << k;
    size_t idx = 0;
    for (int i = 0; i < ndim; ++i)
        idx = (idx << k) | std::min(static_cast<uint32_t>(p[i] * res), res - 1);
    width = w / res;
    return values[nd->index + idx];
}

double Tree::smallestLeaf(uint32_t n) const {
    const Node& nd = nodes[n];
    if (nd.log2GR >= 0) return 1.0 / (1u << nd.log2GR);
    double m = 1;
    for (unsigned c = 0; c < (1u << ndim); ++c) m = std::min(m, smallestLeaf(nd.index + c));
    return .5 * m;
}

// Mean value over a box of the unit hypercube (RADIANCE SDavgTreBox: sub-boxes weighted
// by their volume, grid cells touched by the box counted whole).
double Tree::boxAverage(uint32_t n, const double bmin[4], const double bmax[4]) const {
    for (int i = 0; i < ndim; ++i)
        if (bmin[i] >= 1 || bmax[i] <= 0 || bmin[i] >= bmax[i]) return 0;
    const Node& nd = nodes[n];
    if (nd.log2GR < 0) {
        double sum = 0, wsum = 1e-20;
        for (unsigned c = 0; c < (1u << ndim); ++c) {
            double smin[4], smax[4], w = 1;
            for (int i = 0; i < ndim && w > 0; ++i) {
                const double off = (c >> i & 1) ? 1 : 0;
                smin[i] = std::max(2 * bmin[i] - off, 0.0);
                smax[i] = std::min(2 * bmax[i] - off, 1.0);
                w = smin[i] < smax[i] ? w * (smax[i] - smin[i]) : 0;
            }
            if (w > 1e-10) {
                sum += w * boxAverage(nd.index + c, smin, smax);
                wsum += w;
            }
        }
        return sum / wsum;
    }
    const int res = 1 << nd.log2GR;
    int lo[4] = {0, 0, 0, 0}, hi[4] = {1, 1, 1, 1};
    for (int i = 0; i < ndim; ++i) {
        lo[i] = bmin[i] <= 0 ? 0 : static_cast<int>(res * bmin[i]);
        hi[i] = bmax[i] >= 1 ? res : static_cast<int>(res * bmax[i] + .999999);
    }
    double sum = 0;
    size_t count = 0;
    forEachGridCell(ndim, nd.log2GR, lo, hi, [&](const int*, size_t idx) {
        sum += values[nd.index + idx];
        ++count;
    });
    return count ? sum / double(count) : 0;
}

float Tree::minimum(uint32_t n) const {
    const Node& nd = nodes[n];
    if (nd.log2GR >= 0) {
        const size_t count = size_t(1) << (ndim * nd.log2GR);
        return *std::min_element(values.begin() + nd.index, values.begin() + nd.index + count);
    }
    float m = HUGE_VALF;
    for (unsigned c = 0; c < (1u << ndim); ++c) m = std::min(m, minimum(nd.index + c));
    return m;
}

// The minimum over the part of the tree that lookups reach: all of a 4-D tree, the
// lower half of dimension 0 (incident radius) of a 3-D one.
float Tree::liveMinimum() const {
    if (ndim != 3) return minimum(0);
    const Node& root = nodes[0];
    if (root.log2GR < 0) {
        float m = HUGE_VALF;
        for (unsigned c = 0; c < 8; c += 2) m = std::min(m, minimum(root.index + c));
        return m;
    }
    if (root.log2GR == 0) return values[root.index];
    const size_t half = size_t(1) << (3 * root.log2GR - 1);
    return *std::min_element(values.begin() + root.index, values.begin() + root.index + half);
}

namespace {

// ---------------------------------------------------------------------------------
// ScatteringData text: "{" then either 2^ndim subtrees or 2^(ndim k) numbers, then "}",
// commas allowed after numbers and nodes (load_tree_data in bsdf_t.c). Errors name the
// line inside the XML file.
class TreeParser {
public:
    TreeParser(const std::string& text, int firstLine, const XmlContext& ctx, Tree& tree)
        : s_(text), firstLine_(firstLine), ctx_(ctx), tree_(tree) {}

    void parse() {
        tree_.nodes.resize(1);
        parseNode(0, 0);
        if (skipSpace() != '\0') fail(pos_, "extra characters after the tensor tree");
    }

private:
    static constexpr int kMaxDepth = kHilbertBits;  // finer cells than 2^-16 not located

    const std::string& s_;
    int firstLine_;
    const XmlContext& ctx_;
    Tree& tree_;
    size_t pos_ = 0;

    [[noreturn]] void fail(size_t at, const std::string& msg) const {
        const int line = firstLine_ + static_cast<int>(std::count(
                                          s_.begin(), s_.begin() + std::min(at, s_.size()), '\n'));
        throw InputError(SourceLoc{ctx_.path(), line}, msg);
    }
    char skipSpace() {
        while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
        return pos_ < s_.size() ? s_[pos_] : '\0';
    }
    void skipComma() {
        if (skipSpace() == ',') ++pos_;
    }
    void parseNode(uint32_t slot, int depth);
    void parseBranch(uint32_t slot, int depth);
    void parseGrid(uint32_t slot, size_t open, int depth);
    float parseNumber();
};

void TreeParser::parseNode(uint32_t slot, int depth) {
    if (skipSpace() != '{') fail(pos_, "expected '{' in tensor tree");
    const size_t open = pos_++;
    if (skipSpace() == '{')
        parseBranch(slot, depth);
    else
        parseGrid(slot, open, depth);
    if (skipSpace() != '}') fail(pos_, "expected '}' in tensor tree");
    ++pos_;
    skipComma();
}

void TreeParser::parseBranch(uint32_t slot, int depth) {
    if (depth >= kMaxDepth) fail(pos_, "tensor tree is too deep (cells finer than 2^-16)");
    const unsigned nchild = 1u << tree_.ndim;
    const auto first = static_cast<uint32_t>(tree_.nodes.size());
    tree_.nodes.resize(first + nchild);
    tree_.nodes[slot] = {-1, first};
    for (unsigned c = 0; c < nchild; ++c) {
        if (skipSpace() != '{')
            fail(pos_, "tensor tree branch has " + std::to_string(c) + " subtrees; " +
                           std::to_string(nchild) + " expected");
        parseNode(first + c, depth + 1);
    }
    if (skipSpace() == '{')
        fail(pos_, "tensor tree branch has more than " + std::to_string(nchild) + " subtrees");
}

void TreeParser::parseGrid(uint32_t slot, size_t open, int depth) {
    const size_t start = tree_.values.size();
    while (true) {
        const char c = skipSpace();
        if (c == '}' || c == '\0') break;
        tree_.values.push_back(parseNumber());
        skipComma();
    }
    const size_t n = tree_.values.size() - start;
    int k = 0;  // n must be 2^(ndim k)
    while ((size_t(1) << (tree_.ndim * k)) < n && tree_.ndim * (k + 1) < 48) ++k;
    if (n == 0 || (size_t(1) << (tree_.ndim * k)) != n)
        fail(open, "tensor tree node has " + std::to_string(n) + " values; a TensorTree" +
                       std::to_string(tree_.ndim) + " node needs 1, " +
                       std::to_string(1u << tree_.ndim) + ", " +
                       std::to_string(1u << 2 * tree_.ndim) + ", ... values (or subtrees)");
    if (depth + k > kMaxDepth) fail(open, "tensor tree is too deep (cells finer than 2^-16)");
    if (start > UINT32_MAX - n) fail(open, "tensor tree too large");
    tree_.nodes[slot] = {k, static_cast<uint32_t>(start)};
}

// A real number as RADIANCE's fskip accepts it ([sign] digits [. digits] [e [sign]
// digits]) making up the whole word; negative values become zero, as in bsdf_t.c.
float TreeParser::parseNumber() {
    const size_t begin = pos_;
    while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_])) &&
           s_[pos_] != ',' && s_[pos_] != '}' && s_[pos_] != '{')
        ++pos_;
    const std::string word = s_.substr(begin, pos_ - begin);
    size_t i = (!word.empty() && (word[0] == '+' || word[0] == '-')) ? 1 : 0;
    const auto digits = [&] {
        const size_t j = i;
        while (i < word.size() && std::isdigit(static_cast<unsigned char>(word[i]))) ++i;
        return i - j;
    };
    size_t nd = digits();
    if (i < word.size() && word[i] == '.') ++i, nd += digits();
    bool ok = nd > 0;
    if (ok && i < word.size() && (word[i] == 'e' || word[i] == 'E')) {
        ++i;
        if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
        ok = digits() > 0;
    }
    if (!ok || i != word.size())
        fail(begin, "bad number '" + (word.empty() ? std::string(1, s_[begin]) : word) +
                        "' in tensor tree");
    const double v = std::strtod(word.c_str(), nullptr);
    // Values are stored as float: a larger one would be infinite (and its sums NaN).
    if (v > std::numeric_limits<float>::max())
        fail(begin, "value '" + word + "' out of range in tensor tree");
    return v > 0 ? static_cast<float>(v) : 0.0f;
}

}  // namespace

Tree parseScatteringData(const pugi::xml_node& block, int ndim, const XmlContext& ctx) {
    const pugi::xml_node basis = block.child("AngleBasis");
    if (!basis) ctx.fail(block, "missing AngleBasis for tensor-tree BSDF data");
    if (!textIs(basis, "LBNL/Shirley-Chiu"))
        ctx.fail(basis, "unsupported angle basis '" + trimmedText(basis) +
                            "' for tensor-tree data (must be LBNL/Shirley-Chiu)");
    const pugi::xml_node data = block.child("ScatteringData");
    pugi::xml_node text = data.first_child();
    while (text && text.type() != pugi::node_pcdata && text.type() != pugi::node_cdata)
        text = text.next_sibling();
    const std::string s = text ? text.value() : "";
    if (s.find_first_not_of(" \t\r\n") == std::string::npos)
        ctx.fail(data ? data : block, "missing BSDF ScatteringData");
    Tree tree;
    tree.ndim = ndim;
    TreeParser(s, ctx.loc(text).line, ctx, tree).parse();
    return tree;
}

}  // namespace rp::bsdf::detail::ttree
