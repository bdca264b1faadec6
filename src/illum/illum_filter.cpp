// IllumFilter (see illum_filter.h).
#include "illum/illum_filter.h"

#include <sys/wait.h>

#include <cstdio>

#include "illum/illum_output.h"
#include "util/warnings.h"

namespace rp::illum {

namespace {

constexpr int kMaxCommandDepth = 32;
constexpr double kFtiny = 1e-6;  // RADIANCE FTINY

std::string shorten(const std::string& s) { return s.size() > 60 ? s.substr(0, 57) + "..." : s; }

// Runs `command` with /bin/sh and returns what it writes (RADIANCE popen).
std::string shellOutput(const std::string& command, const SourceLoc& loc) {
    std::fflush(nullptr);
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) throw InputError(loc, "cannot run command: !" + shorten(command));
    std::string text;
    char buf[65536];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) text.append(buf, n);
    const int status = ::pclose(pipe);
    if (status == -1 || WIFSIGNALED(status) || WEXITSTATUS(status) != 0)
        throw InputError(loc, "command failed: !" + shorten(command));
    return text;
}

std::string describe(const InputObject& o) { return o.typeName + " '" + o.name + "'"; }

}  // namespace

IllumFilter::IllumFilter(const IllumTracer& tracer, std::ostream& out, std::string header,
                         std::string directory, CommandHook commands)
    : tracer_(tracer),
      out_(out),
      header_(std::move(header)),
      directory_(std::move(directory)),
      commands_(std::move(commands)) {}

IllumFilter::~IllumFilter() = default;

void IllumFilter::process(std::string_view text, const std::string& name) {
    process(text, name, 0);
    out().flush();
    if (!out()) throw InputError("error writing the output");
}

void IllumFilter::process(std::string_view text, const std::string& name, int depth) {
    InputReader reader(text, name);
    for (InputItem item = reader.next(); item.kind != InputItem::Kind::kEnd; item = reader.next()) {
        switch (item.kind) {
            case InputItem::Kind::kComment:
                comment(item.text, item.loc);
                break;
            case InputItem::Kind::kCommand:
                command(item.text, item.loc, depth);
                break;
            default:
                object(item.object);
        }
    }
}

void IllumFilter::checkHeader() {
    if (headerDone_) return;
    headerDone_ = true;
    out() << "# " << header_ << "\n#@mkillum !\n";
}

void IllumFilter::comment(const std::string& line, const SourceLoc& loc) {
    if (!isOptionLine(line)) {  // not ours: copied as it is
        out() << line;
        return;
    }
    const OptionLine o = applyOptionLine(line, settings_, loc);
    if (o.processed) {
        // RADIANCE compat: mkillum's own output passes through unchanged.
        warn(loc, "already processed by mkillum: nothing in it is converted");
        settings_.selection = Selection::kNone;
        return;
    }
    if (o.outputFile) {
        auto file = std::make_unique<std::ofstream>(*o.outputFile, std::ios::trunc);
        if (!*file) throw InputError(loc, "cannot open output file '" + *o.outputFile + "'");
        out().flush();
        file_ = std::move(file);
        headerDone_ = false;
    }
    checkHeader();
    out() << "# " << line.substr(2);  // "#@mkillum ..." becomes "# mkillum ..."
}

void IllumFilter::command(const std::string& command, const SourceLoc& loc, int depth) {
    if (depth >= kMaxCommandDepth)
        throw InputError(loc, "commands nested too deeply: !" + shorten(command));
    std::optional<std::string> output;
    if (commands_) output = commands_(command, loc);
    if (!output) output = shellOutput(command, loc);
    try {
        process(*output, "!" + command, depth + 1);
    } catch (const InputError& e) {
        if (e.message().find(" (in output of !") != std::string::npos) throw;
        throw InputError(loc, e.message() + " (in output of !" + shorten(command) + ")");
    }
}

void IllumFilter::object(const InputObject& o) {
    if (o.isAlias()) {  // RADIANCE compat: copied before any header
        out() << formatAlias(o);
        return;
    }
    checkHeader();
    if (!isSurface(o.type) || !settings_.selects(o.modifier)) {
        copy(o);
        return;
    }
    bool converted = false;
    switch (o.type) {
        case PrimType::Polygon:
            converted = convertFace(o);
            break;
        case PrimType::Sphere:
            converted = convertSphere(o);
            break;
        case PrimType::Ring:
            converted = convertRing(o);
            break;
        default:
            break;
    }
    if (!converted) {
        warn(o.loc, "cannot make illum for " + describe(o));
        copy(o);
    }
}

void IllumFilter::copy(const InputObject& o) { out() << formatObject(o.modifier, o); }

bool IllumFilter::convertFace(const InputObject& o) {
    const Face face = makeFace(o);
    if (face.area == 0) {
        warn(o.loc, describe(o) + " has no area");
        return false;
    }
    FlatFrame frame;
    const std::optional<Distribution> d = sampleFace(face, settings_, tracer_, nextRay_, frame);
    if (!d) {
        warn(o.loc, describe(o) + " is too thin to sample in its bounding rectangle");
        return false;
    }
    finish(o, *d, &frame);
    return true;
}

bool IllumFilter::convertRing(const InputObject& o) {
    const Ring ring = makeRing(o);
    FlatFrame frame;
    finish(o, sampleRing(ring, settings_, tracer_, nextRay_, frame), &frame);
    return true;
}

bool IllumFilter::convertSphere(const InputObject& o) {
    const Sphere sphere = makeSphere(o);
    finish(o, sampleSphere(sphere, settings_, tracer_, nextRay_), nullptr);
    return true;
}

void IllumFilter::finish(const InputObject& o, const Distribution& d, const FlatFrame* frame) {
    const Color average = d.average();
    if (!(illumBrightness(average) > settings_.minBrightness + kFtiny)) {
        copy(o);  // too dark to be worth a source
        return;
    }
    if (settings_.density > 0) {
        out() << (frame ? writeFlatDistribution(settings_, d, average, *frame, directory_)
                        : writeRoundDistribution(settings_, d, average, directory_));
    } else if (!frame) {
        warn(o.loc, describe(o) + ": diffuse distribution");  // RADIANCE compat (my_sphere)
    }
    out() << formatIllum(settings_, o.modifier, average, o);
}

}  // namespace rp::illum
