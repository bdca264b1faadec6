// See modifier_table.h. An alias is compared as RADIANCE stores it (radiance_objects.h):
// type alias, its target as modifier or as a named string argument, no reals.
#include "scene/modifier_table.h"

namespace rp {

namespace {

constexpr double kTiny = 1e-6;  // FTINY
const std::vector<std::string> kNoStrings;
const std::vector<double> kNoReals;

// modobject.c eqreal(): relative difference within FTINY (absolute against zero).
bool equalReal(double d1, double d2) {
    if (d2 != 0.0) d1 = d1 / d2 - 1.0;
    return -kTiny <= d1 && d1 <= kTiny;
}

// A record as RADIANCE holds it.
struct View {
    int type;  // PrimType, or -1 for an alias
    int32_t modifier;
    const std::vector<std::string>* sargs;
    const std::vector<double>* rargs;
    std::vector<std::string> aliasArg;
};

View view(const std::vector<Primitive>& prims, int32_t i) {
    const Primitive& p = prims[size_t(i)];
    if (p.aliasOf < 0) return {int(p.type), p.modifier, &p.sargs, &p.rargs, {}};
    View v{-1, p.aliasNamed ? p.modifier : p.aliasOf, &kNoStrings, &kNoReals, {}};
    if (p.aliasNamed) v.aliasArg = {prims[size_t(p.aliasOf)].name};
    return v;
}

// How many leading string arguments name modifiers (eqobjects' special cases).
size_t modifierArgs(int type, size_t nsargs) {
    if (type == -1 || type == int(PrimType::Illum) || type == int(PrimType::Mirror))
        return nsargs > 0;
    if (type == int(PrimType::Mixfunc) || type == int(PrimType::Mixdata) ||
        type == int(PrimType::Mixtext) || type == int(PrimType::Mixpict))
        return nsargs >= 2 ? 2 : 0;
    if (type == int(PrimType::Antimatter)) return nsargs;
    return 0;
}

class Comparer {
public:
    Comparer(const std::vector<Primitive>& prims,
             const std::unordered_map<std::string, int32_t>& table)
        : prims_(prims), table_(table) {}

    bool equal(int32_t a, int32_t b) const {
        while (a != b) {
            if (a == kVoid || b == kVoid) return false;
            const View va = view(prims_, a), vb = view(prims_, b);
            const auto& sa = va.type == -1 ? va.aliasArg : *va.sargs;
            const auto& sb = vb.type == -1 ? vb.aliasArg : *vb.sargs;
            if (va.type != vb.type || sa.size() != sb.size() ||
                va.rargs->size() != vb.rargs->size())
                return false;
            if (prims_[size_t(a)].iargs != prims_[size_t(b)].iargs) return false;
            for (size_t i = va.rargs->size(); i-- > 0;)
                if (!equalReal((*va.rargs)[i], (*vb.rargs)[i])) return false;
            const size_t n = modifierArgs(va.type, sa.size());
            for (size_t i = sa.size(); i-- > n;)
                if (sa[i] != sb[i]) return false;
            for (size_t i = n; i-- > 0;)
                if (!equal(lastModifier(a, sa[i]), lastModifier(b, sb[i]))) return false;
            a = va.modifier;
            b = vb.modifier;
        }
        return true;
    }

private:
    // lastmod(): the modifier `name` stood for when record `before` was read.
    int32_t lastModifier(int32_t before, const std::string& name) const {
        const auto it = table_.find(name);
        const int32_t i = it == table_.end() ? kVoid : it->second;
        if (before == kVoid || i < before) return i;
        for (int32_t k = before; k-- > 0;) {
            const Primitive& p = prims_[size_t(k)];
            if (isModifier(p.type) && p.name == name) return k;
        }
        return kVoid;
    }

    const std::vector<Primitive>& prims_;
    const std::unordered_map<std::string, int32_t>& table_;
};

}  // namespace

bool radianceEqualObjects(const std::vector<Primitive>& prims,
                          const std::unordered_map<std::string, int32_t>& table, int32_t a,
                          int32_t b) {
    return Comparer(prims, table).equal(a, b);
}

}  // namespace rp
