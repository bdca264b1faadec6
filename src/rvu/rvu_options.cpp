// rvu's command line (see rvu_options.h).
#include "rvu/rvu_options.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "util/bool_option.h"
#include "util/error.h"

namespace rp::rvu {

RvuOptions rvuDefaults() {
    RvuOptions o;
    render::RpictOptions& p = o.picture;
    p.sampleSpacing = 8;
    p.sampleThreshold = 0.15;
    render::RenderOptions& r = p.render;
    // RADIANCE compat (rvmain.c): rvu trades accuracy for speed more than rpict does.
    r.direct.threshold = 0.1;
    r.direct.certainty = 0.25;
    r.direct.relays = 0;
    r.direct.pretest = 128;
    r.direct.sampling = 0;
    r.specular.threshold = 0.3;
    r.specular.sampling = 1;
    r.limits.maxDepth = 6;
    r.limits.minWeight = 1e-2;
    r.ambient.accuracy = 0.3;
    r.ambient.resolution = 32;
    r.ambient.divisions = 256;
    r.ambient.supersamples = 64;
    // RADIANCE compat (raycalls.c rand_samp): rvu samples uncorrelated, rpict does not.
    r.uncorrelated = true;
    return o;
}

namespace {

double exposureValue(const std::string& s) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end || !std::isfinite(v))
        throw InputError("bad value for -pe: '" + s + "' (expected a number)");
    // RADIANCE compat (rvmain.c): a sign means f-stops.
    const double e = (s[0] == '+' || s[0] == '-') ? std::pow(2.0, v) : v;
    if (!(e > 0)) throw InputError("bad value for -pe: exposure must be positive");
    return e;
}

void setDevice(RvuOptions& o, const std::string& spec) {
    const std::string name = spec.substr(0, spec.find(':'));
    if (name != "web")
        throw InputError("unknown output device \"" + name + "\" (rvu -devices lists them)");
    o.device = name;
    if (spec.size() > name.size()) {
        const std::string port = spec.substr(name.size() + 1);
        char* end = nullptr;
        errno = 0;
        const long v = std::strtol(port.c_str(), &end, 10);
        if (port.empty() || port.find_first_not_of("0123456789") != std::string::npos || *end ||
            errno || v < 0 || v > 65535)
            throw InputError("bad port in -o " + spec + " (expected web:PORT, 0 to 65535)");
        o.port = int(v);
    }
}

}  // namespace

RvuCommand parseRvuCommand(std::vector<std::string> args) {
    RvuCommand cmd;
    cmd.options = rvuDefaults();
    RvuOptions& o = cmd.options;
    auto own = [&](const std::vector<std::string>& a, size_t& i) {
        const std::string& w = a[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= a.size()) throw InputError("missing value for " + w);
            return a[++i];
        };
        if (w == "-o") {
            setDevice(o, value());
        } else if (w == "-pe") {
            o.exposure = exposureValue(value());
        } else if (w.rfind("-b", 0) == 0 && w.size() <= 3 && w != "-bv") {
            o.greyscale = boolSuffix(w, 2, o.greyscale);  // -b toggles, -b+ -by -b0 ...
        } else if (w == "-devices") {
            cmd.printDevices = true;
        } else if (w == "-z" || w == "-r" || w == "-ro" || w == "-S" || w == "-t" || w == "-pd" ||
                   w == "-pm" || w == "-P" || w == "-PP") {
            // RADIANCE compat (rvu.1): rpict options that have no meaning here.
            throw InputError("option '" + w + "' is rpict's, not rvu's");
        } else {
            return false;
        }
        ++i;
        return true;
    };
    render::RpictCommand r = render::parseRpictCommand(std::move(args), o.picture, own);
    o.picture = r.options;
    cmd.sceneFiles = std::move(r.sceneFiles);
    cmd.printDefaults = r.printDefaults;
    cmd.printVersion = r.printVersion;
    return cmd;
}

std::string formatRvuDefaults(const RvuOptions& o) {
    std::string s;
    s += fmt::format("-n {}\t\t\t\t# number of rendering threads\n", o.picture.render.threads);
    const std::string device = o.port > 0 ? fmt::format("{}:{}", o.device, o.port) : o.device;
    s += fmt::format("-o {}\t\t\t\t# output device\n", device);
    s += fmt::format("-pe {:f}\t\t\t# exposure\n", o.exposure);
    s += o.greyscale ? "-b+\t\t\t\t# greyscale on\n" : "-b-\t\t\t\t# greyscale off\n";
    // rpict's lines, less those of the options rvu refuses.
    std::istringstream lines(render::formatRpictDefaults(o.picture));
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("-pm ", 0) == 0 || line.rfind("-pd ", 0) == 0 || line.rfind("-t ", 0) == 0)
            continue;
        s += line + '\n';
    }
    return s;
}

std::string formatRvuDevices() {
    return "web              # a page in your web browser (rvu prints its address)\n";
}

}  // namespace rp::rvu
