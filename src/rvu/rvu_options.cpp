// rvu's command line (see rvu_options.h).
#include "rvu/rvu_options.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "util/error.h"
#include "util/options.h"

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
    const std::optional<double> v = parseReal(s);
    if (!v) throw InputError("bad value for -pe: '" + s + "' (expected a number)");
    // RADIANCE compat (rvmain.c): a sign means f-stops.
    const double e = (s[0] == '+' || s[0] == '-') ? std::pow(2.0, *v) : *v;
    if (!(e > 0)) throw InputError("bad value for -pe: exposure must be positive");
    return e;
}

// rvu's messages for its own values, as rpict's ("missing value for -o").
const OptionMessages& rvuMessages() {
    static const OptionMessages m = [] {
        OptionMessages r;
        r.missing = [](const std::string& opt) { return "missing value for " + opt; };
        return r;
    }();
    return m;
}

void setDevice(RvuOptions& o, const std::string& spec) {
    std::string name = spec.substr(0, spec.find(':'));
    // RADIANCE's window devices (rad -o x11, objview) open the one display there is here.
    if (name == "x11" || name == "qt" || name == "x11dev") name = "web";
    if (name != "web")
        throw InputError("unknown output device \"" + name + "\" (rvu -devices lists them)");
    o.device = name;
    if (const std::size_t colon = spec.find(':'); colon != std::string::npos) {
        const std::string port = spec.substr(colon + 1);
        const std::optional<long> v = parseInteger(port);
        if (port.find_first_not_of("0123456789") != std::string::npos || !v || *v < 0 || *v > 65535)
            throw InputError("bad port in -o " + spec + " (expected web:PORT, 0 to 65535)");
        o.port = int(*v);
    }
}

// rvu's own options, ahead of rpict's (rpict_options.h addRpictOptions).
void addRvuOptions(OptionTable& t, RvuCommand& cmd) {
    RvuOptions& o = cmd.options;
    t.add(render::threadsOption(o.picture.render.threads), [&o] {
        return fmt::format("-n {}\t\t\t\t# number of rendering threads\n",
                           o.picture.render.threads);
    });
    OptionSpec device = customOption("-o", [&o](OptionReader& r) { setDevice(o, r.word()); });
    device.messages = &rvuMessages();
    t.add(device, [&o] {
        const std::string d = o.port > 0 ? fmt::format("{}:{}", o.device, o.port) : o.device;
        return fmt::format("-o {}\t\t\t\t# output device\n", d);
    });
    t.add(customOption("-R", [&o](OptionReader& r) { o.radFile = r.word(); }));
    OptionSpec exposure =
        customOption("-pe", [&o](OptionReader& r) { o.exposure = exposureValue(r.word()); });
    exposure.messages = &rvuMessages();
    t.add(exposure, [&o] { return fmt::format("-pe {:f}\t\t\t# exposure\n", o.exposure); });
    // -b toggles, -b+ -by -b0 ... (not -bv, the common back-face option).
    auto grey = [](const std::string& w) {
        return w.rfind("-b", 0) == 0 && w.size() <= 3 && w != "-bv";
    };
    t.add(customOption(
              grey, "-b",
              [&o](OptionReader& r) { o.greyscale = boolSuffix(r.option(), 2, o.greyscale); }),
          [&o] {
              return std::string(o.greyscale ? "-b+\t\t\t\t# greyscale on\n"
                                             : "-b-\t\t\t\t# greyscale off\n");
          });
    t.add(customOption("-devices", [&cmd](OptionReader&) { cmd.printDevices = true; }));
    // RADIANCE compat (rvu.1): rpict options that have no meaning here (nor -defaults lines).
    for (const char* name : {"-z", "-r", "-ro", "-S", "-t", "-pd", "-pm", "-P", "-PP"})
        t.add(customOption(name, [](OptionReader& r) {
            throw InputError("option '" + r.option() + "' is rpict's, not rvu's");
        }));
}

void addRvuTable(OptionTable& t, RvuCommand& cmd) {
    render::addRpictOptions(t, cmd.options.picture,
                            [&cmd](OptionTable& t) { addRvuOptions(t, cmd); });
}

}  // namespace

RvuCommand parseRvuCommand(std::vector<std::string> args) {
    RvuCommand cmd;
    cmd.options = rvuDefaults();
    OptionTable t;
    addRvuTable(t, cmd);
    render::RpictCommand r;  // scene files and -defaults/-version; the options are cmd's
    render::finishRpictCommand(t, std::move(args), r);
    cmd.sceneFiles = std::move(r.sceneFiles);
    cmd.printDefaults = r.printDefaults;
    cmd.printVersion = r.printVersion;
    return cmd;
}

std::string formatRvuDefaults(const RvuOptions& o) {
    RvuCommand cmd;
    cmd.options = o;
    OptionTable t;
    addRvuTable(t, cmd);
    return t.formatDefaults();
}

std::string formatRvuDevices() {
    return "web              # a page in your web browser (rvu prints its address)\n";
}

}  // namespace rp::rvu
