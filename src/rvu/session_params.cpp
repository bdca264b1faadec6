// rvu's set, new, trace and its rad-file views L and V (see session.h).
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <functional>

#include "image/tonemap.h"
#include "rvu/session.h"
#include "rvu/session_words.h"

namespace rp::rvu {

namespace {

// One variable of rvu's set command (RADIANCE rv2.c setparam), typed as RADIANCE's
// getparam: b(oolean), i(nteger), r(eal), C(olour).
struct Variable {
    const char* key;
    const char* description;
    char kind;
    std::function<void*(RvuOptions&)> where;
};

const std::vector<Variable>& variables() {
    using O = RvuOptions;
    static const std::vector<Variable> v{
        {"aa", "ambient accuracy", 'r',
         [](O& o) -> void* { return &o.picture.render.ambient.accuracy; }},
        {"ab", "ambient bounces", 'i',
         [](O& o) -> void* { return &o.picture.render.ambient.bounces; }},
        {"ad", "ambient divisions", 'i',
         [](O& o) -> void* { return &o.picture.render.ambient.divisions; }},
        {"ar", "ambient resolution", 'i',
         [](O& o) -> void* { return &o.picture.render.ambient.resolution; }},
        {"as", "ambient super-samples", 'i',
         [](O& o) -> void* { return &o.picture.render.ambient.supersamples; }},
        {"av", "ambient value", 'C', [](O& o) -> void* { return &o.picture.render.ambient.value; }},
        {"aw", "ambient value weight", 'i',
         [](O& o) -> void* { return &o.picture.render.ambient.valueWeight; }},
        {"b", "black and white", 'b', [](O& o) -> void* { return &o.greyscale; }},
        {"bv", "back face visibility", 'b',
         [](O& o) -> void* { return &o.picture.render.backVisible; }},
        {"dc", "direct certainty", 'r',
         [](O& o) -> void* { return &o.picture.render.direct.certainty; }},
        {"dj", "direct jitter", 'r', [](O& o) -> void* { return &o.picture.render.direct.jitter; }},
        {"ds", "direct sampling", 'r',
         [](O& o) -> void* { return &o.picture.render.direct.sampling; }},
        {"dt", "direct threshold", 'r',
         [](O& o) -> void* { return &o.picture.render.direct.threshold; }},
        {"dv", "direct visibility", 'b',
         [](O& o) -> void* { return &o.picture.render.direct.visibility; }},
        {"i", "irradiance", 'b', [](O& o) -> void* { return &o.picture.render.irradiance; }},
        {"lr", "limit reflection", 'i',
         [](O& o) -> void* { return &o.picture.render.limits.maxDepth; }},
        {"lw", "limit weight", 'r',
         [](O& o) -> void* { return &o.picture.render.limits.minWeight; }},
        {"ma", "scattering albedo", 'C',
         [](O& o) -> void* { return &o.picture.render.mist.albedo; }},
        {"me", "extinction coefficient", 'C',
         [](O& o) -> void* { return &o.picture.render.mist.extinction; }},
        {"mg", "scattering eccentricity", 'r',
         [](O& o) -> void* { return &o.picture.render.mist.eccentricity; }},
        {"ms", "mist sampling distance", 'r',
         [](O& o) -> void* { return &o.picture.render.mist.samplingDistance; }},
        {"ps", "pixel sample", 'i', [](O& o) -> void* { return &o.picture.sampleSpacing; }},
        {"pt", "pixel threshold", 'r', [](O& o) -> void* { return &o.picture.sampleThreshold; }},
        {"ss", "specular sampling", 'r',
         [](O& o) -> void* { return &o.picture.render.specular.sampling; }},
        {"st", "specular threshold", 'r',
         [](O& o) -> void* { return &o.picture.render.specular.threshold; }},
        {"u", "uncorrelated sampling", 'b',
         [](O& o) -> void* { return &o.picture.render.uncorrelated; }},
    };
    return v;
}

std::string showValue(const Variable& v, void* p) {
    switch (v.kind) {
        case 'b':
            return *static_cast<bool*>(p) ? "y" : "n";
        case 'i':
            return std::to_string(*static_cast<int*>(p));
        case 'r':
            return fmt::format("{:g}", *static_cast<double*>(p));
        default: {
            const Color& c = *static_cast<Color*>(p);
            return fmt::format("{:g} {:g} {:g}", c.r, c.g, c.b);
        }
    }
}

// Sets the variable from `words`; returns whether its value changed.
bool assign(const Variable& v, void* p, const std::vector<std::string>& words) {
    switch (v.kind) {
        case 'b': {
            const char c = words[0][0];
            const std::string yes = "yY+1tT", no = "nN-0fF";
            if (yes.find(c) == std::string::npos && no.find(c) == std::string::npos)
                throw InputError("expected y or n for " + std::string(v.description));
            const bool b = yes.find(c) != std::string::npos;
            const bool changed = *static_cast<bool*>(p) != b;
            *static_cast<bool*>(p) = b;
            return changed;
        }
        case 'i': {
            const double d = number(words[0], v.description);
            if (d != std::floor(d) || std::fabs(d) > 1e9)
                throw InputError("expected an integer for " + std::string(v.description));
            const bool changed = *static_cast<int*>(p) != int(d);
            *static_cast<int*>(p) = int(d);
            return changed;
        }
        case 'r': {
            const double d = number(words[0], v.description);
            const bool changed = *static_cast<double*>(p) != d;
            *static_cast<double*>(p) = d;
            return changed;
        }
        default: {
            if (words.size() != 3)
                throw InputError("expected 3 values for " + std::string(v.description));
            const Color c{number(words[0], v.description), number(words[1], v.description),
                          number(words[2], v.description)};
            Color& old = *static_cast<Color*>(p);
            const bool changed = old.r != c.r || old.g != c.g || old.b != c.b;
            old = c;
            return changed;
        }
    }
}

}  // namespace

CommandResult Session::set(const std::string& args) {
    auto words = splitWords(args);
    if (words.empty()) {
        std::string keys;
        for (const Variable& v : variables()) keys += std::string(keys.empty() ? "" : " ") + v.key;
        return success(keys);
    }
    const Variable* var = nullptr;
    for (const Variable& v : variables())
        if (words[0] == v.key) var = &v;
    if (!var) return failure(words[0] + ": unknown variable");
    void* p = var->where(setup_.options);
    words.erase(words.begin());
    if (words.empty()) return success(fmt::format("{} ({})", var->description, showValue(*var, p)));
    if (!assign(*var, p, words)) return success("");
    const std::string key = var->key;
    if (key == "b") {
        greyscale_ = setup_.options.greyscale;
    } else if (key == "ps" || key == "pt") {
        // RADIANCE compat (setparam): sampling changes go on refining this picture.
        image_->setSampling(setup_.options.picture.sampleSpacing,
                            setup_.options.picture.sampleThreshold);
    } else {
        newParams_ = true;
        return success(fmt::format("{} set to {} (\"new\" renders with it)", var->description,
                                   showValue(*var, p)));
    }
    return success("");
}

CommandResult Session::newImage(const std::string& args) {
    const auto words = splitWords(args);
    if (!words.empty()) {
        const double n = number(words[0], "process count");
        if (n < 1 || n != std::floor(n) || n > 1024) return failure("new: bad process count");
        setup_.options.picture.render.threads = int(n);
    }
    if (newParams_) rebuildRenderer();
    restartImage();
    return success("");
}

CommandResult Session::trace(const std::string& args, const std::vector<Cursor>& cursor) {
    const auto words = splitWords(args);
    std::optional<render::RayResult> hit;
    if (words.size() == 6) {
        const Vec3 org{number(words[0], "origin"), number(words[1], "origin"),
                       number(words[2], "origin")};
        const Vec3 dir{number(words[3], "direction"), number(words[4], "direction"),
                       number(words[5], "direction")};
        if (length(dir) == 0) return failure("zero ray direction");
        hit = traceAllPasses(org, normalize(dir), HUGE_VAL);
    } else if (!words.empty()) {
        return failure("trace: expected xbeg ybeg zbeg xdir ydir zdir");
    } else if (cursor.empty()) {
        return pickRequest("Pick ray", 1);
    } else {
        const Cursor c = clampCursor(cursor[0], image_->width(), image_->height());
        auto ray = ViewRays(image_->view())
                       .ray((c.x + 0.5) / image_->width(), (c.y + 0.5) / image_->height());
        if (!ray) return failure("not on image");
        hit = traceAllPasses(ray->origin, ray->direction,
                             ray->maxDistance > 0 ? ray->maxDistance : HUGE_VAL);
    }
    if (!hit->hit) return success("ray hit nothing");
    // RADIANCE compat (rv2.c traceray): what was hit, where, and the value.
    const Scene& scene = *setup_.scene;
    std::string what = dot(hit->direction, hit->unperturbedNormal) > 0 ? "back of " : "";
    what += hit->modifier >= 0 ? scene.prims[size_t(hit->modifier)].name : "void";
    if (hit->material >= 0 && hit->material != hit->modifier)
        what += " (" + scene.prims[size_t(hit->material)].name + ")";
    const Primitive& surface = scene.prims[size_t(hit->prim)];
    std::string out =
        fmt::format("ray hit {} {} \"{}\"\n", what, primTypeName(surface.type), surface.name);
    out += fmt::format("at ({:.6g} {:.6g} {:.6g}) ({:.6g})\n", hit->point.x, hit->point.y,
                       hit->point.z, hit->distance);
    const Pixel v{float(hit->value.r), float(hit->value.g), float(hit->value.b)};
    out += fmt::format("value ({:.5g} {:.5g} {:.5g}) ({:.3g}L)", hit->value.r, hit->value.g,
                       hit->value.b, 179.0 * pixelBrightness(v));
    return success(out);
}

CommandResult Session::loadRadView(const std::string& args) {
    // RADIANCE's L runs rad to expand a rad file's view; we read its "view=" lines
    // ourselves: by number (1 = the first) or by name (the word after "view=").
    const auto words = splitWords(args);
    const std::string which = words.empty() ? "1" : words[0];
    if (words.size() > 1) radFile_ = words[1];
    if (radFile_.empty()) return failure("no previous rad file");
    std::ifstream in(radFile_);
    if (!in) return failure("cannot access \"" + radFile_ + "\"");
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        const size_t at = line.find("view=");
        if (at == std::string::npos || trim(line.substr(0, at)).size() > 0) continue;
        ++n;
        const auto parts = splitWords(line.substr(at + 5));
        const std::string name = !parts.empty() && parts[0][0] != '-' ? parts[0] : "";
        if (which != std::to_string(n) && which != name) continue;
        View v;
        if (applyViewString(v, line.substr(at + 5)) == 0)
            return failure("view \"" + which +
                           "\" has no view options (rad's standard views need rad)");
        return changeView(v);
    }
    return failure("rad error -- no such view?");
}

CommandResult Session::saveRadView(const std::string& args) {
    const auto words = splitWords(args);
    std::string name;
    if (!words.empty()) {
        name = words[0];
        if (name.find_first_not_of("0123456789") == std::string::npos)
            return failure("cannot write view by number");
    }
    if (words.size() > 1) radFile_ = words[1];
    if (radFile_.empty()) return failure("no previous rad file");
    std::ofstream out(radFile_, std::ios::app);
    if (out) out << "view= " << name << formatView(view_) << '\n';
    if (!out) return failure("cannot open \"" + radFile_ + "\"");
    return success("");
}

}  // namespace rp::rvu
