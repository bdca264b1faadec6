#include "material/pattern.h"

#include <algorithm>

#include "calc/search_path.h"
#include "material/function_space.h"

namespace rp::material {

namespace {

// Whether an expression's text names a ray variable that depends on the point (P, N, T,
// Rdot) rather than only the direction. Only meaningful when no function file is loaded
// (a file can read P under any name).
bool mentionsPosition(const std::string& text) {
    for (const char* v : {"Px", "Py", "Pz", "Nx", "Ny", "Nz", "Rdot", "T"}) {
        size_t at = text.find(v);
        while (at != std::string::npos) {
            size_t end = at + std::char_traits<char>::length(v);
            bool startOk = at == 0 || !(std::isalnum((unsigned char)text[at - 1]) || text[at - 1] == '_');
            bool endOk = end >= text.size() || !(std::isalnum((unsigned char)text[end]) || text[end] == '_');
            if (startOk && endOk) return true;
            at = text.find(v, at + 1);
        }
    }
    return false;
}

}  // namespace

PatternSet::PatternSet(const Scene& scene, std::vector<std::string> searchPath)
    : scene_(scene), patternOf_(scene.prims.size(), -1) {
    calc::Builder builder(std::move(searchPath));
    builder.loadFile("rayinit.cal");
    std::vector<std::string> loaded;
    for (size_t i = 0; i < scene.prims.size(); ++i) {
        const Primitive& p = scene.prims[i];
        if (p.type != PrimType::Brightfunc && p.type != PrimType::Colorfunc) continue;
        Pattern pat;
        pat.prim = int32_t(i);
        pat.colour = p.type == PrimType::Colorfunc;
        size_t nfunc = pat.colour ? 3 : 1;
        // ray.html: funcs..., funcfile, transform. The reader checked the counts.
        const std::string& file = p.sargs.at(nfunc);
        if (file != "." && std::find(loaded.begin(), loaded.end(), file) == loaded.end()) {
            try {
                builder.loadFile(file);
            } catch (const InputError& e) {
                // Syntax errors keep their own file:line; a missing file is reported at
                // the primitive that names it.
                if (e.loc().line > 0) throw;
                throw InputError(p.loc, std::string(primTypeName(p.type)) + " '" + p.name +
                                            "': " + e.what());
            }
            loaded.push_back(file);
        }
        Transform forward = parseTransform(p.sargs, nfunc + 1, p.loc);
        pat.toObject = forward.inverse();
        pat.usesPosition = false;
        for (size_t k = 0; k < nfunc; ++k) {
            pat.expr[k] = builder.addExpression(p.sargs[k], p.loc);
            pat.usesPosition = pat.usesPosition || mentionsPosition(p.sargs[k]);
        }
        // A function file can read P anywhere; only rayinit-only patterns are trusted to
        // be directional from their expression text alone.
        if (file != ".") pat.usesPosition = true;
        patternOf_[i] = int32_t(patterns_.size());
        patterns_.push_back(pat);
    }
    program_ = builder.build();
}

void PatternSet::checkChain(int32_t modifier) const {
    for (int32_t m = modifier; m != kVoid; m = scene_.prims[m].modifier) {
        const Primitive& p = scene_.prims[m];
        if (patternOf_[m] < 0)
            throw notSupportedYet(p.loc, std::string(primTypeName(p.type)) + " modifier '" +
                                             p.name + "' in this position");
    }
}

bool PatternSet::directionalOnly(int32_t modifier) const {
    for (int32_t m = modifier; m != kVoid; m = scene_.prims[m].modifier)
        if (patternOf_[m] < 0 || patterns_[patternOf_[m]].usesPosition) return false;
    return true;
}

PatternEvaluator::PatternEvaluator(const PatternSet& set) : set_(set), eval_(set.program_) {}

Color PatternEvaluator::chainColor(int32_t modifier, const PatternPoint& at) {
    Color c{1, 1, 1};
    for (int32_t m = modifier; m != kVoid; m = set_.scene_.prims[m].modifier) {
        const PatternSet::Pattern& pat = set_.patterns_[set_.patternOf_[m]];
        const Primitive& p = set_.scene_.prims[m];
        calc::RayContext ctx = functionSpace(at, pat.toObject);
        ctx.args = p.rargs;
        eval_.setRay(ctx);
        if (pat.colour) {
            c.r *= eval_.eval(set_.program_->expression(pat.expr[0]));
            c.g *= eval_.eval(set_.program_->expression(pat.expr[1]));
            c.b *= eval_.eval(set_.program_->expression(pat.expr[2]));
        } else {
            c *= eval_.eval(set_.program_->expression(pat.expr[0]));
        }
    }
    return c;
}

}  // namespace rp::material
