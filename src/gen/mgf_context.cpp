// MGF contexts: colours, materials, vertices, object names and transforms (RADIANCE's
// mgf_context.c, mgf_object.c and mgf_xf.c, rewritten). Checks and error codes follow
// RADIANCE, so that the same input fails on the same line.
#include <cstdlib>

#include "gen/mgf_reader.h"

namespace rp::gen {

namespace {

double num(const std::string& s) { return std::atof(s.c_str()); }

// The "c", "m" and "v" entities share one grammar: "e" selects the unnamed context (reset
// to the default), "e name" an existing one, "e name =" (re)defines it from the default
// and "e name = template" from another. Returns the selected context or nullptr (unnamed).
template <class T>
T* selectContext(std::map<std::string, T>& table, T& unnamed, const MgfArgs& args,
                 std::string* nameOut) {
    if (args.size() > 4) mgfFail(MgfError::ArgCount);
    if (args.size() == 1) {
        unnamed = T();
        if (nameOut) nameOut->clear();
        return &unnamed;
    }
    if (!mgfIsName(args[1])) mgfFail(MgfError::IllegalValue);
    auto it = table.find(args[1]);
    if (args.size() == 2) {
        if (it == table.end()) mgfFail(MgfError::Undefined);
        if (nameOut) *nameOut = args[1];
        return &it->second;
    }
    if (args[2] != "=") mgfFail(MgfError::ArgType);
    T value;
    if (args.size() == 4) {
        auto tmpl = table.find(args[3]);
        if (tmpl == table.end()) mgfFail(MgfError::Undefined);
        value = tmpl->second;
    }
    T& slot = table[args[1]];
    slot = value;
    if (nameOut) *nameOut = args[1];
    return &slot;
}

}  // namespace

void MgfReader::colorEntity(const MgfArgs& args) {
    const std::string& e = args[0];
    if (e == "c") {
        color_ = selectContext(colors_, unnamedColor_, args, nullptr);
        return;
    }
    MgfColor& c = *color_;
    if (e == "cxy") {
        if (args.size() != 3) mgfFail(MgfError::ArgCount);
        if (!mgfIsFloat(args[1]) || !mgfIsFloat(args[2])) mgfFail(MgfError::ArgType);
        if (!c.setXy(num(args[1]), num(args[2]))) mgfFail(MgfError::IllegalValue);
    } else if (e == "cspec") {
        if (args.size() < 5) mgfFail(MgfError::ArgCount);
        if (!mgfIsFloat(args[1]) || !mgfIsFloat(args[2])) mgfFail(MgfError::ArgType);
        std::vector<float> values;
        for (size_t i = 3; i < args.size(); ++i) {
            if (!mgfIsFloat(args[i])) mgfFail(MgfError::ArgType);
            values.push_back(float(num(args[i])));
        }
        if (!c.setSpectrum(num(args[1]), num(args[2]), values, dither_))
            mgfFail(MgfError::IllegalValue);
    } else {  // cct
        if (args.size() != 2) mgfFail(MgfError::ArgCount);
        if (!mgfIsFloat(args[1])) mgfFail(MgfError::ArgType);
        if (!c.setBlackBody(num(args[1]), dither_)) mgfFail(MgfError::IllegalValue);
    }
}

void MgfReader::mixEntity(const MgfArgs& args) {
    if (args.size() < 5 || (args.size() - 1) % 2) mgfFail(MgfError::ArgCount);
    auto named = [&](const std::string& name) {
        auto it = colors_.find(name);
        if (it == colors_.end()) mgfFail(MgfError::Undefined);
        return it->second;
    };
    if (!mgfIsFloat(args[1])) mgfFail(MgfError::ArgType);
    double wsum = num(args[1]);
    MgfColor mix = named(args[2]);
    for (size_t i = 3; i < args.size(); i += 2) {
        if (!mgfIsFloat(args[i])) mgfFail(MgfError::ArgType);
        double w = num(args[i]);
        mix = mixColors(wsum, mix, w, named(args[i + 1]), dither_);
        wsum += w;
    }
    if (wsum <= 0) mgfFail(MgfError::IllegalValue);
    *color_ = mix;
}

void MgfReader::materialEntity(const MgfArgs& args) {
    // A (re)definition counts as a change of the material, so mgf2rad prints it again.
    int oldClock = 0;
    if (args.size() >= 3) {
        auto it = materials_.find(args[1]);
        if (it != materials_.end()) oldClock = it->second.clock;
    }
    material_ = selectContext(materials_, unnamedMaterial_, args, &materialName_);
    if (args.size() >= 3) material_->clock = oldClock + 1;
}

void MgfReader::materialProperty(const MgfArgs& args) {
    const std::string& e = args[0];
    MgfMaterial& m = *material_;
    size_t want = (e == "ir" || e == "rs" || e == "ts") ? 3 : 2;
    if (args.size() != want) mgfFail(MgfError::ArgCount);
    if (e == "sides") {
        if (!mgfIsInt(args[1])) mgfFail(MgfError::ArgType);
        int n = std::atoi(args[1].c_str());
        if (n != 1 && n != 2) mgfFail(MgfError::IllegalValue);
        m.oneSided = n == 1;
        ++m.clock;
        return;
    }
    for (size_t i = 1; i < want; ++i)
        if (!mgfIsFloat(args[i])) mgfFail(MgfError::ArgType);
    float a = float(num(args[1]));
    float b = want == 3 ? float(num(args[2])) : 0.f;
    auto fraction = [](float v) { return v >= 0 && v <= 1; };
    bool ok = true;
    if (e == "ir") {
        m.nr = a, m.ni = b, ok = m.nr > 1e-6f;
    } else if (e == "rd") {
        m.rd = a, m.rdColor = *color_, ok = fraction(a);
    } else if (e == "td") {
        m.td = a, m.tdColor = *color_, ok = fraction(a);
    } else if (e == "ed") {
        m.ed = a, m.edColor = *color_, ok = a >= 0;
    } else if (e == "rs") {
        m.rs = a, m.rsRough = b, m.rsColor = *color_, ok = fraction(a) && b >= 0;
    } else {  // ts
        m.ts = a, m.tsRough = b, m.tsColor = *color_, ok = fraction(a) && b >= 0;
    }
    if (!ok) mgfFail(MgfError::IllegalValue);
    ++m.clock;
}

void MgfReader::vertexEntity(const MgfArgs& args) {
    vertex_ = selectContext(vertices_, unnamedVertex_, args, nullptr);
}

void MgfReader::vertexProperty(const MgfArgs& args) {
    if (args.size() != 4) mgfFail(MgfError::ArgCount);
    for (int i = 1; i < 4; ++i)
        if (!mgfIsFloat(args[i])) mgfFail(MgfError::ArgType);
    Vec3 v{num(args[1]), num(args[2]), num(args[3])};
    if (args[0] == "p") {
        vertex_->p = v;
    } else {
        mgfNormalize(v);
        vertex_->n = v;
    }
}

const MgfVertex* MgfReader::vertex(const std::string& name) const {
    auto it = vertices_.find(name);
    return it == vertices_.end() ? nullptr : &it->second;
}

void MgfReader::objectEntity(const MgfArgs& args) {
    if (args.size() == 1) {
        if (objects_.empty()) mgfFail(MgfError::ContextClose);
        objects_.pop_back();
        return;
    }
    if (args.size() != 2) mgfFail(MgfError::ArgCount);
    if (!mgfIsName(args[1])) mgfFail(MgfError::IllegalValue);
    objects_.push_back(args[1]);
}

// ---- transforms ----

void MgfReader::xfEntity(const MgfArgs& args) {
    if (args.size() > 1) return xfPush(args);
    if (xf_.empty()) mgfFail(MgfError::ContextClose);
    XfSpec& spec = *xf_.back();
    if (spec.dims.empty()) return xfPop();
    // The end of one array element: count on (last dimension fastest) and read the body
    // again, or leave the array.
    arrayName(nullptr);
    int d = int(spec.dims.size());
    while (d--) {
        if (++spec.dims[d].i < spec.dims[d].n) break;
        spec.dims[d].i = 0;
        spec.args[spec.dims[d].argIndex].assign(1, '0');
    }
    if (d < 0) return xfPop();
    File& file = *files_.back();
    if (file.id != spec.fileId) mgfFail(MgfError::Seek);
    file.next = spec.restartLine;
    spec.args[spec.dims[d].argIndex] = std::to_string(spec.dims[d].i);
    arrayName(&spec);
    computeXf(spec);
}

void MgfReader::xfPush(const MgfArgs& args) {
    auto spec = std::make_unique<XfSpec>();
    for (size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "-a" && i + 1 < args.size()) {
            // An array dimension of n copies: "-i k" for copy k = 0 .. n-1.
            spec->args.push_back("-i");
            spec->dims.push_back({0, std::atoi(args[i + 1].c_str()), spec->args.size()});
            spec->args.push_back("0");
            ++i;
        } else {
            spec->args.push_back(args[i]);
        }
    }
    if (spec->dims.size() > 8) mgfFail(MgfError::OutOfMemory);  // RADIANCE's XF_MAXDIM
    if (!spec->dims.empty()) {
        File& file = *files_.back();
        spec->fileId = file.id;
        spec->restartLine = file.next;
        arrayName(spec.get());
    }
    xf_.push_back(std::move(spec));
    computeXf(*xf_.back());
}

void MgfReader::xfPop() { xf_.pop_back(); }

void MgfReader::computeXf(XfSpec& spec) {
    Transform own;
    try {
        own = parseTransform(spec.args, 0, SourceLoc{});
    } catch (const InputError&) {
        mgfFail(MgfError::ArgType);
    }
    const XfSpec* prev = xf_.size() > 1 ? xf_[xf_.size() - 2].get() : nullptr;
    spec.xf = prev ? prev->xf * own : own;
    spec.rev = own.mirrors() != (prev && prev->rev);
}

void MgfReader::arrayName(const XfSpec* spec) {
    if (!spec) return objectEntity({"o"});
    // RADIANCE names array element (i, j, ...) "ai.j...".
    std::string name = "a";
    for (size_t d = 0; d < spec->dims.size(); ++d) {
        if (d) name += '.';
        name += spec->args[spec->dims[d].argIndex];
    }
    objectEntity({"o", name});
}

Vec3 MgfReader::xfPoint(const Vec3& p) const {
    return xf_.empty() ? p : xf_.back()->xf.mapPoint(p);
}

Vec3 MgfReader::xfVector(const Vec3& v) const {
    return xf_.empty() ? v : xf_.back()->xf.mapDirection(v);
}

Vec3 MgfReader::rotVector(const Vec3& v) const {
    return xf_.empty() ? v : xf_.back()->xf.mapDirection(v) / xf_.back()->xf.scale;
}

double MgfReader::xfScale(double d) const { return xf_.empty() ? d : d * xf_.back()->xf.scale; }

bool MgfReader::reversed() const { return !xf_.empty() && xf_.back()->rev; }

}  // namespace rp::gen
