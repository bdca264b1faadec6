// Klems matrices (LBNL's fixed angle bases), as RADIANCE's bsdf_m.c reads and uses them:
// a basis is a list of latitude bands, each cut into equal azimuth patches; a matrix holds
// one BSDF value per (incident patch, outgoing patch). The four scattering sets differ only
// in how a patch index maps to a direction (which hemisphere, and the incident side's
// azimuth turned by 180 degrees, so that index 0 of both is the straight-through pair).
#include <strings.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "bsdf/colour.h"
#include "bsdf/klems_basis.h"
#include "bsdf/multi_sample.h"
#include "bsdf/xml_detail.h"

namespace rp::bsdf::detail {

namespace {

using Latitude = KlemsLatitude;
using AngleBasis = KlemsBasis;

std::vector<AngleBasis> standardBases() { return standardKlemsBases(); }

double sq(double x) { return x * x; }

constexpr double kDeg = kPi / 180;

Vec3 patchVector(const AngleBasis& b, int ndx, double rx, double ry) {
    return klemsPatchVector(b, ndx, rx, ry);
}

int patchIndex(const AngleBasis& b, const Vec3& v) {
    if (v.z < 0 || v.z > 1.00001) return -1;
    const double pol = std::acos(std::min(v.z, 1.0)) / kDeg;
    double azi = std::atan2(v.y, v.x) / kDeg;
    if (azi < 0) azi += 360;
    std::size_t li = 1;
    for (; b.lat[li].thetaMin <= pol; ++li)
        if (!b.lat[li].nphis) return -1;
    --li;
    int ndx = static_cast<int>(azi / 360 * b.lat[li].nphis + .5);
    if (ndx >= b.lat[li].nphis) ndx = 0;
    while (li--) ndx += b.lat[li].nphis;
    return ndx;
}

// Projected solid angle of a patch (bsdf_m.c io_getohm), -1 for a bad index.
double patchOmega(const AngleBasis& b, int ndx) {
    if (ndx < 0 || ndx >= b.nangles) return -1;
    std::size_t li = 0;
    while (ndx >= b.lat[li].nphis) ndx -= b.lat[li++].nphis;
    return kPi *
           (sq(std::cos(kDeg * b.lat[li].thetaMin)) - sq(std::cos(kDeg * b.lat[li + 1].thetaMin))) /
           b.lat[li].nphis;
}

// How a side's index maps to a local direction: the +Z patch vector with x, y and z
// negated as flagged (front incident: -x -y; back incident: all; back exiting: -z).
struct Side {
    bool flipXY = false, flipZ = false;
    Vec3 apply(Vec3 v) const {
        if (flipXY) v.x = -v.x, v.y = -v.y;
        if (flipZ) v.z = -v.z;
        return v;
    }
};
constexpr Side kFrontIn{true, false}, kBackIn{true, true}, kFrontOut{false, false},
    kBackOut{false, true};

struct Axis {
    const AngleBasis* basis;
    Side side;
    int index(const Vec3& v) const { return patchIndex(*basis, side.apply(v)); }
    Vec3 vector(int ndx, double rx, double ry) const {
        return side.apply(patchVector(*basis, ndx, rx, ry));
    }
    double omega(int ndx) const { return patchOmega(*basis, ndx); }
};

// Cumulative distribution over the outgoing patches for one incident patch.
struct Cdf {
    std::vector<double> c;  // c[0] = 0 ... c[n] = total
};

class KlemsMatrix final : public Distribution {
public:
    KlemsMatrix(Axis in, Axis out) : in_(in), out_(out) {
        values_.assign(static_cast<std::size_t>(in.basis->nangles) * out.basis->nangles, 0.f);
    }
    int ninc() const { return in_.basis->nangles; }
    int nout() const { return out_.basis->nangles; }
    // Colour data (CIE-X and CIE-Z beside the visible Y): RADIANCE RGB per entry.
    void setColour(const std::vector<float>& x, const std::vector<float>& z) {
        rgb_.resize(values_.size() * 3);
        for (std::size_t k = 0; k < values_.size(); ++k) {
            const Color c = rgbOfXyz(x[k], values_[k], z[k]);
            for (int i = 0; i < 3; ++i) rgb_[3 * k + i] = static_cast<float>(c[i]);
        }
    }
    bool coloured() const override { return !rgb_.empty(); }
    std::vector<float>& rgb() { return rgb_; }
    float& at(int o, int i) { return values_[static_cast<std::size_t>(o) * ninc() + i]; }
    float at(int o, int i) const { return values_[static_cast<std::size_t>(o) * ninc() + i]; }
    std::vector<float>& values() { return values_; }
    const Axis& inAxis() const { return in_; }
    const Axis& outAxis() const { return out_; }

    // Tables for sampling, built once the values are final (after the diffuse part is
    // taken out): one per incident patch, and one per outgoing patch for reciprocal use.
    void buildCdfs() {
        forward_.assign(ninc(), {});
        reverse_.assign(nout(), {});
        for (int i = 0; i < ninc(); ++i) {
            auto& c = forward_[i].c;
            c.assign(nout() + 1, 0.0);
            for (int o = 0; o < nout(); ++o) c[o + 1] = c[o] + at(o, i) * out_.omega(o);
        }
        for (int o = 0; o < nout(); ++o) {
            auto& c = reverse_[o].c;
            c.assign(ninc() + 1, 0.0);
            for (int i = 0; i < ninc(); ++i) c[i + 1] = c[i] + at(o, i) * in_.omega(i);
        }
    }

    Color value(const Vec3& inV, const Vec3& outV) const override {
        int i = in_.index(inV), o = out_.index(outV);
        if (i < 0 && o < 0) {  // reciprocity (bsdf_m.c SDgetMtxBSDF)
            i = in_.index(outV);
            o = out_.index(inV);
        }
        if (i < 0 || o < 0) return {};
        return colour(o, i);
    }
    // The entry for outgoing patch o and incident patch i, in RGB.
    Color colour(int o, int i) const {
        if (rgb_.empty()) return Color::grey(at(o, i));
        const float* c = &rgb_[3 * (static_cast<std::size_t>(o) * ninc() + i)];
        return {c[0], c[1], c[2]};
    }

    void projectedSolidAngle(const Vec3& v1, const Vec3* v2p, SizeQuery q,
                             double psa[2]) const override {
        const Vec3& v2 = v2p ? *v2p : v1;
        double outPsa = out_.omega(out_.index(v1));
        double incPsa = in_.omega(in_.index(v2));
        if (v2p && outPsa <= 0 && incPsa <= 0) {
            incPsa = out_.omega(out_.index(v2));
            outPsa = in_.omega(in_.index(v1));
        }
        if (q == SizeQuery::Max) {
            psa[0] = std::max({psa[0], incPsa, outPsa});
            return;
        }
        if (q == SizeQuery::MinMax) psa[1] = std::max({psa[1], incPsa, outPsa});
        if (incPsa > 0 && incPsa < psa[0]) psa[0] = incPsa;
        if (outPsa > 0 && outPsa < psa[0]) psa[0] = outPsa;
    }

    double hemispherical(const Vec3& inV) const override {
        const Cdf* c = cdfFor(inV).first;
        return c ? c->c.back() : 0.0;
    }

    bool sample(const Vec3& inV, double x, double, Vec3& out) const override {
        const auto [cdf, reversed] = cdfFor(inV);
        if (!cdf || cdf->c.back() <= 1e-6) return false;
        const auto& c = cdf->c;
        const double target = std::clamp(x, 0.0, 1.0) * c.back();
        // The last patch with c[k] <= target and a non-zero width.
        auto it = std::upper_bound(c.begin() + 1, c.end(), target);
        int k = static_cast<int>(it - c.begin()) - 1;
        k = std::clamp(k, 0, static_cast<int>(c.size()) - 2);
        while (k > 0 && c[k + 1] <= c[k]) --k;
        const double width = c[k + 1] - c[k];
        // The position inside the patch from what is left of x (bsdf_m.c fo_getvec):
        // the same direction as RADIANCE's for the same x; y is not needed.
        double t[2];
        multiSample2(width > 0 ? std::clamp((target - c[k]) / width, 0.0, 1.0) : .5, t);
        out = reversed ? in_.vector(k, t[0], t[1]) : out_.vector(k, t[0], t[1]);
        return true;
    }

private:
    std::pair<const Cdf*, bool> cdfFor(const Vec3& inV) const {
        if (const int i = in_.index(inV); i >= 0) return {&forward_[i], false};
        if (const int o = out_.index(inV); o >= 0) return {&reverse_[o], true};
        return {nullptr, false};
    }

    Axis in_, out_;
    std::vector<float> values_;  // Y, for sampling and sizes
    std::vector<float> rgb_;     // colour data: RGB per entry (else grey)
    std::vector<Cdf> forward_, reverse_;
};

// A basis defined in the file (bsdf_m.c load_angle_basis); standard names are kept.
void loadBasis(const pugi::xml_node& wab, const XmlContext& ctx, std::vector<AngleBasis>& bases) {
    const std::string name = trimmedText(wab.child("AngleBasisName"));
    if (name.empty()) ctx.fail(wab, "AngleBasis without AngleBasisName");
    for (const AngleBasis& b : bases)
        if (strcasecmp(b.name.c_str(), name.c_str()) == 0) return;
    AngleBasis b{name, 0, {{0, 0}}};
    for (pugi::xml_node blk : wab.children("AngleBasisBlock")) {
        pugi::xml_node bounds = blk.child("ThetaBounds");
        const double upper = std::atof(bounds.child_value("UpperTheta"));
        if (b.lat.size() > 1 && std::abs(std::atof(bounds.child_value("LowerTheta")) -
                                         b.lat.back().thetaMin) > 1e-6 * upper)
            ctx.fail(blk, "theta values disagree in angle basis '" + name + "'");
        const int nphis = std::atoi(blk.child_value("nPhis"));
        if (nphis <= 0 || (nphis == 1 && b.lat.back().thetaMin > 1e-6))
            ctx.fail(blk, "illegal phi count in angle basis '" + name + "'");
        b.lat.back().nphis = nphis;
        b.nangles += nphis;
        b.lat.push_back({upper, 0});
    }
    if (b.nangles == 0) ctx.fail(wab, "angle basis '" + name + "' has no AngleBasisBlock");
    bases.push_back(std::move(b));
}

const AngleBasis& findBasis(const pugi::xml_node& wdb, const char* tag, const XmlContext& ctx,
                            const std::vector<AngleBasis>& bases) {
    const std::string name = trimmedText(wdb.child(tag));
    if (name.empty()) ctx.fail(wdb, std::string("missing ") + tag);
    for (const AngleBasis& b : bases)
        if (strcasecmp(b.name.c_str(), name.c_str()) == 0) return b;
    ctx.fail(wdb.child(tag), std::string("unknown ") + tag + " '" + name + "'");
}

// Reads `n` numbers (blank- or comma-separated) into the matrix, failing at the line of
// the first bad or missing one.
void readValues(const pugi::xml_node& sdNode, const XmlContext& ctx, bool rows, KlemsMatrix& m) {
    const char* text = sdNode.child_value();
    const char* p = text;
    const int ninc = m.ninc(), nout = m.nout();
    const int n = ninc * nout;
    const int line0 = ctx.loc(sdNode).line;
    auto lineAt = [&](const char* q) {
        return line0 + static_cast<int>(std::count(text, q, '\n'));
    };
    for (int k = 0; k < n; ++k) {
        while (*p && (std::isspace(static_cast<unsigned char>(*p)) || *p == ',')) ++p;
        char* end = nullptr;
        const double v = std::strtod(p, &end);
        if (end == p) {
            const std::string what =
                *p ? "bad number in ScatteringData" : "too few values in ScatteringData";
            throw InputError(SourceLoc{ctx.path(), lineAt(p)},
                             what + " (" + std::to_string(k) + " of " + std::to_string(n) + ")");
        }
        // Values are stored as float: a larger one would be infinite (its sums NaN).
        if (!(v <= std::numeric_limits<float>::max()))
            throw InputError(SourceLoc{ctx.path(), lineAt(p)},
                             "value out of range in ScatteringData (" + std::to_string(k) + " of " +
                                 std::to_string(n) + ")");
        p = end;
        const float val = static_cast<float>(v < 0 ? 0 : v);  // negative values are noise
        if (rows)
            m.at(k % nout, k / nout) = val;
        else
            m.values()[k] = val;
    }
    while (*p && (std::isspace(static_cast<unsigned char>(*p)) || *p == ',')) ++p;
    if (*p)
        throw InputError(SourceLoc{ctx.path(), lineAt(p)},
                         "more than " + std::to_string(n) + " values in ScatteringData");
}

// The non-diffuse set a WavelengthDataDirection names (WINDOW's front is our back), and
// the direction mapping of its matrix.
struct SetChoice {
    std::optional<ScatteringSet>* set;
    Side in, out;
};

SetChoice chooseSet(const pugi::xml_node& wdb, const XmlContext& ctx, BsdfData& sd) {
    pugi::xml_node dir = wdb.child("WavelengthDataDirection");
    if (textIs(dir, "Transmission Front")) return {&sd.tb, kBackIn, kFrontOut};
    if (textIs(dir, "Transmission Back")) return {&sd.tf, kFrontIn, kBackOut};
    if (textIs(dir, "Reflection Front")) return {&sd.rb, kBackIn, kBackOut};
    if (textIs(dir, "Reflection Back")) return {&sd.rf, kFrontIn, kFrontOut};
    ctx.fail(dir ? dir : wdb, "unknown WavelengthDataDirection '" + trimmedText(dir) + "'");
}

// Takes the minimum of the matrix out as a Lambertian part (bsdf_m.c subtract_min: only
// where it is worth a reflectance of .01), returned as a hemispherical value.
Color extractDiffuse(KlemsMatrix& m) {
    if (!m.coloured()) {
        float lo = HUGE_VALF;
        for (float v : m.values()) lo = std::min(lo, v);
        if (!(lo > .01 / kPi)) return {};
        for (float& v : m.values()) v -= lo;
        return Color::grey(kPi * lo);
    }
    // Colour: the minimum of each channel (bsdf_m.c subtracts a coloured minimum), its
    // brightness taken from Y.
    float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF};
    std::vector<float>& rgb = m.rgb();
    for (std::size_t k = 0; k < rgb.size(); ++k) lo[k % 3] = std::min(lo[k % 3], rgb[k]);
    const Color c{lo[0], lo[1], lo[2]};
    const double ylo = c.brightness();
    if (!(ylo > .01 / kPi)) return {};
    for (std::size_t k = 0; k < rgb.size(); ++k) rgb[k] = std::max(0.0f, rgb[k] - lo[k % 3]);
    for (float& v : m.values()) v = std::max(0.0f, static_cast<float>(v - ylo));
    return c * kPi;
}

// minProjSA and maxHemi of a one-matrix set (bsdf_m.c get_extrema).
void setExtrema(ScatteringSet& s, const KlemsMatrix& m) {
    s.minProjSA = kPi;
    s.maxHemi = 0;
    for (int o = 0; o < m.nout(); ++o) s.minProjSA = std::min(s.minProjSA, m.outAxis().omega(o));
    for (int i = 0; i < m.ninc(); ++i) {
        double hemi = 0;
        for (int o = 0; o < m.nout(); ++o) hemi += m.outAxis().omega(o) * m.at(o, i);
        s.maxHemi = std::max(s.maxHemi, hemi);
    }
    if (m.inAxis().basis != m.outAxis().basis)
        for (int i = 0; i < m.ninc(); ++i) s.minProjSA = std::min(s.minProjSA, m.inAxis().omega(i));
}

}  // namespace

void loadKlems(const pugi::xml_node& layer, const XmlContext& ctx, BsdfData& sd) {
    pugi::xml_node def = layer.child("DataDefinition");
    pugi::xml_node ids = def.child("IncidentDataStructure");
    bool rows;
    if (textIs(ids, "Rows"))
        rows = true;
    else if (textIs(ids, "Columns"))
        rows = false;
    else
        ctx.fail(ids ? ids : layer, "unsupported IncidentDataStructure '" + trimmedText(ids) + "'");
    std::vector<AngleBasis> bases = standardBases();
    for (pugi::xml_node wab : def.children("AngleBasis")) loadBasis(wab, ctx, bases);
    // The bases are referred to by the matrices: keep them with the data.
    auto shared = std::make_shared<std::vector<AngleBasis>>(std::move(bases));
    std::optional<ScatteringSet>* sets[4] = {&sd.rf, &sd.rb, &sd.tf, &sd.tb};
    // The visible (Y) matrices become the sets; CIE-X and CIE-Z matrices of the same
    // size, where both are given, colour them (bsdf_m.c encode_chroma).
    std::vector<float> xz[4][2];
    for (pugi::xml_node wld : layer.children("WavelengthData")) {
        const pugi::xml_node wl = wld.child("Wavelength");
        const int channel = textIs(wl, "Visible") ? 0
                            : textIs(wl, "CIE-X") ? 1
                            : textIs(wl, "CIE-Z") ? 2
                                                  : -1;
        if (channel < 0) continue;
        for (pugi::xml_node wdb : wld.children("WavelengthDataBlock")) {
            const SetChoice ch = chooseSet(wdb, ctx, sd);
            const AngleBasis& ib = findBasis(wdb, "ColumnAngleBasis", ctx, *shared);
            const AngleBasis& ob = findBasis(wdb, "RowAngleBasis", ctx, *shared);
            auto m = std::make_unique<KlemsMatrix>(Axis{&ib, ch.in}, Axis{&ob, ch.out});
            pugi::xml_node sdNode = wdb.child("ScatteringData");
            if (!sdNode || trimmedText(sdNode).empty()) ctx.fail(wdb, "missing ScatteringData");
            readValues(sdNode, ctx, rows, *m);
            const int k = static_cast<int>(std::find(sets, sets + 4, ch.set) - sets);
            if (channel > 0) {
                xz[k][channel - 1] = std::move(m->values());
                continue;
            }
            // A later block for the same set replaces an earlier one, as in RADIANCE.
            if (!*ch.set) ch.set->emplace();
            (*ch.set)->components.clear();
            (*ch.set)->components.push_back(std::move(m));
        }
    }
    sd.keepAlive = shared;
    Color* lamb[4] = {&sd.rLambFront, &sd.rLambBack, &sd.tLambFront, &sd.tLambBack};
    for (int k = 0; k < 4; ++k) {
        if (!*sets[k]) continue;
        ScatteringSet& s = **sets[k];
        auto& m = static_cast<KlemsMatrix&>(*s.components.front());
        if (xz[k][0].size() == m.values().size() && xz[k][1].size() == m.values().size())
            m.setColour(xz[k][0], xz[k][1]);
        setExtrema(s, m);
        *lamb[k] = extractDiffuse(m);
        s.maxHemi -= lamb[k]->brightness();
        m.buildCdfs();
    }
    // One transmission direction serves both (bsdf_m.c).
    if (sd.tb && !sd.tf)
        sd.tLambFront = sd.tLambBack;
    else if (sd.tf && !sd.tb)
        sd.tLambBack = sd.tLambFront;
}

}  // namespace rp::bsdf::detail

namespace rp::bsdf {

namespace {

using detail::KlemsMatrix;

// The Lambertian part alone (cmbsdf.c cm_bsdf_Lamb): 145 x 145 on the Klems Full basis.
CoefficientMatrix lambertianCoefficients(const Color& bsdf) {
    const KlemsBasis& full = standardKlemsBases().front();
    CoefficientMatrix m{full.nangles, full.nangles, {}};
    m.values.resize(static_cast<std::size_t>(m.rows) * m.cols);
    for (int c = 0; c < m.cols; ++c)
        for (int r = 0; r < m.rows; ++r)
            m.values[static_cast<std::size_t>(r) * m.cols + c] = bsdf * detail::patchOmega(full, c);
    return m;
}

// One entry (cmbsdf.c cm_bsdf): the BSDF of outgoing patch o and incident patch i with
// the Lambertian part added back, times the projected solid angle. RADIANCE zeroes an
// entry whose non-diffuse part is not positive; at the data's minimum that part is what
// rounding leaves of it in RADIANCE's chroma encoding (the entries of a grey file at its
// minimum come out as the Lambertian part alone), so here only an absent value is zero.
Color entry(const KlemsMatrix& m, int o, int i, const Color& diffuse, double omega) {
    if (!(m.at(o, i) >= 0) || !(omega > 0)) return {};
    return (m.colour(o, i) + diffuse) * omega;
}

}  // namespace

CoefficientMatrix klemsCoefficients(const BsdfData& d, MatrixPart part) {
    const ScatteringSet* set = nullptr;
    Color diffuse;
    bool reciprocal = false;
    switch (part) {
        case MatrixPart::Transmission:
            // cmbsdf.c cm_loadBTDF: light arriving from the back (outside), else the
            // front's data by reciprocity.
            reciprocal = !d.tb;
            set = reciprocal ? (d.tf ? &*d.tf : nullptr) : &*d.tb;
            diffuse = (reciprocal ? d.tLambFront : d.tLambBack) * (1 / kPi);
            break;
        case MatrixPart::ReflectionFront:
            set = d.rf ? &*d.rf : nullptr;
            diffuse = d.rLambFront * (1 / kPi);
            break;
        case MatrixPart::ReflectionBack:
            set = d.rb ? &*d.rb : nullptr;
            diffuse = d.rLambBack * (1 / kPi);
            break;
    }
    if (!set) return lambertianCoefficients(diffuse);
    const auto* m = set->components.size() == 1
                        ? dynamic_cast<const KlemsMatrix*>(set->components.front().get())
                        : nullptr;
    if (!m) throw InputError(SourceLoc{d.path, 0}, "unsupported BSDF (not one Klems matrix)");
    // cmbsdf.c cm_bsdf_recip, with only the front's data: rows and columns swap roles,
    // each index carried to the other side by reversing its patch's centre direction
    // through the surface.
    auto across = [](const detail::Axis& from, int k, const detail::Axis& to) {
        const Vec3 v = from.vector(k, .5, .5);
        const int j = to.index({v.x, v.y, -v.z});
        return j < 0 ? k : j;
    };
    const detail::Axis &in = m->inAxis(), &outAxis = m->outAxis();
    CoefficientMatrix out{
        reciprocal ? m->ninc() : m->nout(), reciprocal ? m->nout() : m->ninc(), {}};
    out.values.resize(static_cast<std::size_t>(out.rows) * out.cols);
    std::vector<int> rowIn(reciprocal ? std::size_t(out.rows) : 0);
    for (int r = 0; r < int(rowIn.size()); ++r) rowIn[std::size_t(r)] = across(outAxis, r, in);
    for (int c = 0; c < out.cols; ++c) {
        const int ro = reciprocal ? across(in, c, outAxis) : -1;
        for (int r = 0; r < out.rows; ++r)
            out.values[static_cast<std::size_t>(r) * out.cols + c] =
                reciprocal ? entry(*m, ro, rowIn[std::size_t(r)], diffuse, outAxis.omega(ro))
                           : entry(*m, r, c, diffuse, in.omega(c));
    }
    return out;
}

}  // namespace rp::bsdf
