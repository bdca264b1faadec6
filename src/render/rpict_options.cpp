// rpict's command line parsing, defaults and picture size (see rpict_options.h).
#include "render/rpict_options.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "render/command_args.h"
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

const std::string& valueOf(const std::vector<std::string>& args, size_t i) {
    if (i + 1 >= args.size()) throw InputError("missing value for " + args[i]);
    return args[i + 1];
}

int intValue(const std::vector<std::string>& args, size_t i) {
    const std::string& s = valueOf(args, i);
    char* end = nullptr;
    errno = 0;
    long v = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end || errno || v < -1000000000L || v > 1000000000L)
        throw InputError("bad value for " + args[i] + ": '" + s + "' (expected an integer)");
    return int(v);
}

double realValue(const std::vector<std::string>& args, size_t i) {
    const std::string& s = valueOf(args, i);
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end || !std::isfinite(v))
        throw InputError("bad value for " + args[i] + ": '" + s + "' (expected a number)");
    return v;
}

// rpict's own options at args[i]; advances i past the values. False if not one of them.
bool parseOwnOption(const std::vector<std::string>& args, size_t& i, RpictCommand& cmd) {
    RpictOptions& o = cmd.options;
    const std::string& a = args[i];
    if (a == "-x" || a == "-y") {
        int v = intValue(args, i);
        if (v <= 0) throw InputError("bad value for " + a + ": resolution must be positive");
        (a == "-x" ? o.xres : o.yres) = v;
        i += 1;
    } else if (a == "-pa") {
        o.pixelAspect = realValue(args, i++);
    } else if (a == "-pj") {
        o.pixelJitter = realValue(args, i++);
    } else if (a == "-ps") {
        o.sampleSpacing = intValue(args, i++);
    } else if (a == "-pt") {
        o.sampleThreshold = realValue(args, i++);
    } else if (a == "-pm") {
        o.motionBlur = realValue(args, i++);
    } else if (a == "-pd") {
        o.apertureBlur = realValue(args, i++);
    } else if (a == "-t") {
        o.reportInterval = intValue(args, i++);
    } else if (a == "-o") {
        o.outputFile = valueOf(args, i++);
    } else if (a == "-z") {
        o.zFile = valueOf(args, i++);
    } else if (a == "-S") {
        o.sequenceStart = intValue(args, i++);
    } else if (a == "-r" || a == "-ro") {
        // RADIANCE compat (rpmain.c): -ro names the recover file and the output file.
        o.recoverFile = valueOf(args, i++);
        if (a == "-ro") o.outputFile = o.recoverFile;
    } else if (a == "-P" || a == "-PP") {
        throw notSupportedYet({}, "persistent processes (" + a + ")");
    } else if (a == "-defaults" || a == "-help") {
        cmd.printDefaults = true;
    } else if (a == "-version") {
        cmd.printVersion = true;
    } else {
        return false;
    }
    i += 1;
    return true;
}

}  // namespace

RpictCommand parseRpictCommand(std::vector<std::string> args, const RpictOptions& defaults,
                               const ToolOptionParser& toolOption) {
    RpictCommand cmd;
    cmd.options = defaults;
    size_t i = 0;
    while (true) {
        // RADIANCE compat (rpmain.c): @file and $EVAR are expanded at option positions.
        expandArgAt(args, i);
        if (i >= args.size()) break;
        const std::string a = args[i];
        // RADIANCE compat (rpmain.c): the first word that is not an option ends them.
        if (a.size() < 2 || a[0] != '-') break;
        if (parseRenderOption(args, i, cmd.options.render)) continue;
        // parseViewOption wants C strings (rebuilt: expansion may have changed args).
        std::vector<const char*> cargs;
        for (size_t k = i; k < args.size(); ++k) cargs.push_back(args[k].c_str());
        if (int n = parseViewOption(cmd.options.view, int(cargs.size()), cargs.data())) {
            i += size_t(n);
            continue;
        }
        if (toolOption && toolOption(args, i)) continue;
        if (parseOwnOption(args, i, cmd)) continue;
        throw InputError("unknown option '" + a + "'");
    }
    for (; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.size() > 1 && a[0] == '-')
            throw InputError("option '" + a + "' after the scene file");
        cmd.sceneFiles.push_back(a);
    }
    return cmd;
}

std::string formatRpictDefaults(const RpictOptions& opt) {
    const View& v = opt.view;
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
    // RADIANCE compat: rpmain.c printdefaults, the same order and layout.
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
    s += fmt::format("-x  {:<9d}\t\t\t# x resolution\n", opt.xres);
    s += fmt::format("-y  {:<9d}\t\t\t# y resolution\n", opt.yres);
    s += fmt::format("-pa {:f}\t\t\t# pixel aspect ratio\n", opt.pixelAspect);
    s += fmt::format("-pj {:f}\t\t\t# pixel jitter\n", opt.pixelJitter);
    s += fmt::format("-pm {:f}\t\t\t# pixel motion\n", opt.motionBlur);
    s += fmt::format("-pd {:f}\t\t\t# pixel depth-of-field\n", opt.apertureBlur);
    s += fmt::format("-ps {:<9d}\t\t\t# pixel sample\n", opt.sampleSpacing);
    s += fmt::format("-pt {:f}\t\t\t# pixel threshold\n", opt.sampleThreshold);
    s += fmt::format("-t  {:<9d}\t\t\t# time between reports\n", opt.reportInterval);
    s += opt.render.warnings ? "-w+\t\t\t\t# warning messages on\n"
                             : "-w-\t\t\t\t# warning messages off\n";
    s += formatRenderDefaults(opt.render);
    return s;
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
