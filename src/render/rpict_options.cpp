// rpict's command line parsing, defaults and picture size (see rpict_options.h).
#include "render/rpict_options.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/error.h"
#include "util/vec.h"

namespace rp::render {

RenderOptions rpictRenderDefaults() {
    // RADIANCE compat: rpict.c's globals (5.4) rather than rtrace.c's. rpict favours
    // speed over accuracy in the direct and ambient calculations.
    RenderOptions o;
    o.direct.threshold = 0.05;
    o.direct.certainty = 0.5;
    o.direct.jitter = 0;
    o.direct.sampling = 0.25;
    o.direct.relays = 1;
    o.direct.pretest = 512;
    o.direct.visibility = true;
    o.specular.sampling = 1.0;
    o.specular.threshold = 0.15;
    o.limits.maxDepth = 7;
    o.limits.minWeight = 1e-3;
    o.ambient.accuracy = 0.2;
    o.ambient.resolution = 64;
    o.ambient.divisions = 512;
    o.ambient.supersamples = 128;
    o.ambient.bounces = 0;
    return o;
}

namespace {

// rpict's own messages, as its options have always said them.
const OptionMessages& rpictMessages() {
    static const OptionMessages m = [] {
        OptionMessages r;
        r.missing = [](const std::string& opt) { return "missing value for " + opt; };
        r.bad = [](const std::string& opt, const std::string& v, ValueKind kind) {
            return "bad value for " + opt + ": '" + v + "' (expected " +
                   (kind == ValueKind::kInteger ? "an integer" : "a number") + ")";
        };
        r.range = [](const std::string& opt, const std::string& what) {
            return "bad value for " + opt + ": " + what;
        };
        return r;
    }();
    return m;
}

OptionSpec own(OptionSpec s) {
    s.messages = &rpictMessages();
    return s;
}

OptionSpec ownInt(const std::string& name, int& v) {
    return own(customOption(
        name, [&v](OptionReader& r) { v = int(r.integer(-1000000000L, 1000000000L)); }));
}

OptionSpec ownReal(const std::string& name, double& v) { return own(valueOption(name, v)); }

std::string viewDefaults(const View& v) {
    const char* typeName = "unknown";
    switch (v.type) {
        case ViewType::kPerspective:
            typeName = "perspective";
            break;
        case ViewType::kParallel:
            typeName = "parallel";
            break;
        case ViewType::kCylindrical:
            typeName = "cylindrical";
            break;
        case ViewType::kHemispherical:
            typeName = "hemispherical";
            break;
        case ViewType::kAngular:
            typeName = "angular";
            break;
        case ViewType::kPlanisphere:
            typeName = "planisphere";
            break;
    }
    std::string s;
    s += fmt::format("-vt{}\t\t\t\t# view type {}\n", char(v.type), typeName);
    s += fmt::format("-vp {:f} {:f} {:f}\t# view point\n", v.point.x, v.point.y, v.point.z);
    s += fmt::format("-vd {:f} {:f} {:f}\t# view direction\n", v.direction.x, v.direction.y,
                     v.direction.z);
    s += fmt::format("-vu {:f} {:f} {:f}\t# view up\n", v.up.x, v.up.y, v.up.z);
    s += fmt::format("-vh {:f}\t\t\t# view horizontal size\n", v.horizontal);
    s += fmt::format("-vv {:f}\t\t\t# view vertical size\n", v.vertical);
    s += fmt::format("-vo {:f}\t\t\t# view fore clipping plane\n", v.fore);
    s += fmt::format("-va {:f}\t\t\t# view aft clipping plane\n", v.aft);
    s += fmt::format("-vs {:f}\t\t\t# view shift\n", v.shift);
    s += fmt::format("-vl {:f}\t\t\t# view lift\n", v.lift);
    return s;
}

std::function<std::string()> realLine(const double& v, const char* name, const char* what) {
    return [&v, name, what] { return fmt::format("{} {:f}\t\t\t# {}\n", name, v, what); };
}

// rpict's -x -y -p? -t, in the order of its -defaults lines (rpmain.c printdefaults).
void addPictureOptions(OptionTable& t, RpictOptions& o) {
    for (const auto& option : {std::pair{"-x", &o.xres}, std::pair{"-y", &o.yres}}) {
        // Plain copies: clang 14 (the fuzz build's compiler) cannot capture a structured
        // binding.
        const char* name = option.first;
        int* v = option.second;
        t.add(own(customOption(name,
                               [v](OptionReader& r) {
                                   const long n = r.integer(-1000000000L, 1000000000L);
                                   r.require(n > 0, "resolution must be positive");
                                   *v = int(n);
                               })),
              [name, v] {
                  return fmt::format("{}  {:<9d}\t\t\t# {} resolution\n", name, *v, name[1]);
              });
    }
    t.add(ownReal("-pa", o.pixelAspect), realLine(o.pixelAspect, "-pa", "pixel aspect ratio"));
    t.add(ownReal("-pj", o.pixelJitter), realLine(o.pixelJitter, "-pj", "pixel jitter"));
    t.add(ownReal("-pm", o.motionBlur), realLine(o.motionBlur, "-pm", "pixel motion"));
    t.add(ownReal("-pd", o.apertureBlur), realLine(o.apertureBlur, "-pd", "pixel depth-of-field"));
    t.add(ownInt("-ps", o.sampleSpacing),
          [&o] { return fmt::format("-ps {:<9d}\t\t\t# pixel sample\n", o.sampleSpacing); });
    t.add(ownReal("-pt", o.sampleThreshold), realLine(o.sampleThreshold, "-pt", "pixel threshold"));
    t.add(ownInt("-t", o.reportInterval), [&o] {
        return fmt::format("-t  {:<9d}\t\t\t# time between reports\n", o.reportInterval);
    });
}

// rpict's options that print no -defaults line.
void addOutputOptions(OptionTable& t, RpictOptions& o) {
    t.add(own(valueOption("-o", o.outputFile)));
    t.add(own(valueOption("-z", o.zFile)));
    t.add(ownInt("-S", o.sequenceStart));
    t.add(own(valueOption("-r", o.recoverFile)));
    // RADIANCE compat (rpmain.c): -ro names the recover file and the output file.
    t.add(own(customOption("-ro", [&o](OptionReader& r) {
        o.recoverFile = r.word();
        o.outputFile = o.recoverFile;
    })));
    for (const char* name : {"-P", "-PP"})
        t.add(customOption(name, [](OptionReader& r) {
            throw notSupportedYet({}, "persistent processes (" + r.option() + ")");
        }));
}

}  // namespace

void addRpictOptions(OptionTable& t, RpictOptions& o,
                     const std::function<void(OptionTable&)>& toolOptions) {
    t.expandArgs = true;
    t.helpIsDefaults = true;
    // A program sharing rpict's command line (rvu) comes first: its options replace
    // rpict's of the same name, and its -defaults lines lead.
    if (toolOptions) toolOptions(t);
    // RADIANCE compat (rpmain.c printdefaults): the view, the picture options, -w and the
    // common options, in this order.
    t.add(viewOptionSpec(o.view), [&o] { return viewDefaults(o.view); });
    addPictureOptions(t, o);
    t.add(warningsOption(o.render.warnings));
    addRenderOptions(t, o.render);
    addOutputOptions(t, o);
}

RpictCommand parseRpictCommand(std::vector<std::string> args, const RpictOptions& defaults) {
    RpictCommand cmd;
    cmd.options = defaults;
    OptionTable t;
    addRpictOptions(t, cmd.options);
    finishRpictCommand(t, std::move(args), cmd);
    return cmd;
}

void finishRpictCommand(const OptionTable& t, std::vector<std::string> args, RpictCommand& cmd) {
    const OptionParse p = t.parse(args, 0);
    cmd.printVersion = p.stop == OptionStop::kVersion;
    cmd.printDefaults = p.stop == OptionStop::kDefaults;
    if (p.stop != OptionStop::kEnd) return;
    for (size_t i = p.next; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.size() > 1 && a[0] == '-')
            throw InputError("option '" + a + "' after the scene file");
        cmd.sceneFiles.push_back(a);
    }
}

std::string formatRpictDefaults(const RpictOptions& opt) {
    RpictOptions copy = opt;
    OptionTable t;
    addRpictOptions(t, copy);
    return t.formatDefaults();
}

double viewAspect(const View& v) {
    const ImagePlaneSize p = imagePlaneSize(v);  // as RADIANCE's setview
    return p.vertical / p.horizontal;
}

PictureSize pictureSize(const RpictOptions& opt) {
    // RADIANCE compat: image.c normaspect, including its rounding (+.5, truncated).
    PictureSize p{opt.xres, opt.yres, opt.pixelAspect};
    const double va = viewAspect(opt.view);
    const double tiny = 1e-6;  // RADIANCE's FTINY
    if (p.pixelAspect <= tiny)
        p.pixelAspect = va * p.xres / p.yres;
    else if (va * p.xres > p.pixelAspect * p.yres)
        p.xres = int(p.yres / va * p.pixelAspect + .5);
    else
        p.yres = int(p.xres * va / p.pixelAspect + .5);
    p.xres = std::max(1, p.xres);
    p.yres = std::max(1, p.yres);
    return p;
}

}  // namespace rp::render
