// rtrace ray input and result formatting (see rtrace_io.h).
#include "render/rtrace_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "image/spectral_picture.h"
#include "util/colr.h"
#include "util/error.h"
#include "util/header.h"

namespace rp::render {

namespace {

constexpr const char* kKnownSpecs = "odvVwWlLcpnNsmMrxRX~";
constexpr const char* kColorSpecs = "vVWrx";

bool isColorSpec(char c) { return std::strchr(kColorSpecs, c) != nullptr; }

}  // namespace

OutputSpec parseOutputSpec(const std::string& spec, char outputFormat) {
    OutputSpec out;
    std::string* into = &out.primary;
    for (size_t k = 0; k < spec.size(); ++k) {
        char c = spec[k];
        if (c == 't' || c == 'T') {
            // RADIANCE compat (rtrace.c setoutput): a trailing t/T is ignored.
            if (k + 1 == spec.size()) break;
            if (into == &out.tree)
                throw InputError("-o: only one 't' or 'T' allowed in '" + spec + "'");
            into = &out.tree;
            out.traceSources = c == 'T';
            continue;
        }
        if (std::strchr(kKnownSpecs, c) == nullptr || c == '\0')
            throw InputError(std::string("unknown output specifier '") + c + "' in -o" + spec);
        if (outputFormat == 'c' && !isColorSpec(c))
            throw InputError(
                std::string("-fc (RGBE) output only for colour values (v V W r x), not '") + c +
                "'");
        *into += c;
    }
    return out;
}

// ---- input ----

bool RayReader::word(std::string& w) {
    // From the stream's buffer: the stream's own get() and peek() build a sentry per
    // character, a twentieth of a run of bare photon lookups.
    using Traits = std::char_traits<char>;
    std::streambuf* const buf = in_.rdbuf();
    w.clear();
    Traits::int_type c = Traits::eof();
    while (buf && !Traits::eq_int_type(c = buf->sbumpc(), Traits::eof())) {
        if (c == '\n') ++line_;
        if (!std::isspace(c)) break;
    }
    if (!buf || Traits::eq_int_type(c, Traits::eof())) {
        in_.setstate(std::ios::eofbit);
        return false;
    }
    wordLine_ = line_;
    w += Traits::to_char_type(c);
    while (!Traits::eq_int_type(c = buf->sgetc(), Traits::eof()) && !std::isspace(c))
        w += Traits::to_char_type(buf->sbumpc());
    return true;
}

RayReader::Status RayReader::next(InputRay& ray) {
    double v[6];
    if (format_ == 'a') {
        std::string w;
        for (int k = 0; k < 6; ++k) {
            if (!word(w)) {
                if (k == 0) return Status::End;
                error_ = "bad ray at input line " + std::to_string(line_) +
                         ": incomplete ray at end of input";
                return Status::Bad;
            }
            // std::from_chars first (the same correctly rounded value, without strtod's
            // locale and setup); strtod for what it alone reads ("+1", hex, "infinity").
            const char* first = w.data();
            const char* last = first + w.size();
            const std::from_chars_result fast = std::from_chars(first, last, v[k]);
            const char* end = fast.ptr;
            if (fast.ec != std::errc() || end != last) {
                char* e = nullptr;
                v[k] = std::strtod(w.c_str(), &e);
                end = e;
            }
            if (end != last) {
                error_ = "bad ray at input line " + std::to_string(wordLine_) + ": '" + w +
                         "' is not a number";
                return Status::Bad;
            }
        }
    } else {
        const size_t size = format_ == 'f' ? sizeof(float) : sizeof(double);
        char buf[6 * sizeof(double)];
        in_.read(buf, std::streamsize(6 * size));
        const std::streamsize got = in_.gcount();
        if (got == 0) return Status::End;
        if (got != std::streamsize(6 * size)) {
            error_ = "incomplete ray at end of input (" + std::to_string(got) + " of " +
                     std::to_string(6 * size) + " bytes)";
            return Status::Bad;
        }
        for (int k = 0; k < 6; ++k) {
            if (format_ == 'f') {
                float f;
                std::memcpy(&f, buf + k * size, size);
                v[k] = f;
            } else {
                std::memcpy(&v[k], buf + k * size, size);
            }
        }
    }
    ray.origin = {v[0], v[1], v[2]};
    ray.direction = {v[3], v[4], v[5]};
    ++rays_;
    return Status::Ok;
}

// ---- output ----

RayWriter::RayWriter(OutputSpec spec, char format, const Scene* scene, ColourOutput colours)
    : spec_(std::move(spec)), format_(format), scene_(scene), colours_(std::move(colours)) {}

void RayWriter::setTraceFilter(const TraceFilter& filter) {
    traceMode_ = filter.mode;
    traceModifiers_ = {filter.modifiers.begin(), filter.modifiers.end()};
}

bool RayWriter::traced(const RayResult& r) const {
    if (traceMode_ == TraceFilter::Mode::kAll) return true;
    // RADIANCE compat (rtrace.c ourtrace): a ray that hits nothing has no modifier: left
    // out by an include list, kept by an exclude list. The list holds modifier names
    // (RADIANCE collects every modifier of that name), so names are compared.
    bool listed = false;
    const bool named = r.hit || r.distantSource;
    if (named && r.modifier >= 0 && scene_ && size_t(r.modifier) < scene_->prims.size())
        listed = traceModifiers_.count(scene_->prims[size_t(r.modifier)].name) > 0;
    if (!named) return traceMode_ == TraceFilter::Mode::kExclude;
    return listed == (traceMode_ == TraceFilter::Mode::kInclude);
}

void RayWriter::real(std::string& out, double v) const {
    if (format_ == 'a') {
        // RADIANCE compat (rtrace.c puta): "%e" then a tab after every value. std::to_chars
        // writes the same characters (both round exactly; "inf", "nan" likewise) at a
        // fraction of printf's cost, which was a tenth of a run of bare photon lookups.
        char buf[40];
        const std::to_chars_result r =
            std::to_chars(buf, buf + sizeof buf - 1, v, std::chars_format::scientific, 6);
        *r.ptr = '\t';
        out.append(buf, size_t(r.ptr + 1 - buf));
    } else if (format_ == 'f') {
        float f = float(v);
        out.append(reinterpret_cast<const char*>(&f), sizeof f);
    } else {
        out.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
}

void RayWriter::color(std::string& out, const Color& c, const std::vector<double>* samples) const {
    if (!colours_.identity()) {
        const double rgb[3] = {c.r, c.g, c.b};
        const std::span<const double> in =
            samples ? std::span<const double>(*samples) : std::span<const double>(rgb, 3);
        double v[spectral::kMaxSamples];
        const std::span<double> conv(v, size_t(colours_.components()));
        colours_.convert(in, conv);
        if (format_ == 'c' && conv.size() > 3) {  // RADIANCE 6's common-exponent samples
            float f[spectral::kMaxSamples];
            uint8_t packed[spectral::kMaxSamples + 1];
            for (size_t i = 0; i < conv.size(); ++i) f[i] = float(conv[i]);
            packSpectrum(std::span<const float>(f, conv.size()),
                         std::span<uint8_t>(packed, conv.size() + 1));
            out.append(reinterpret_cast<const char*>(packed), conv.size() + 1);
            return;
        }
        if (format_ == 'c') {  // three components (fewer are refused when parsed)
            Colr colr = toColr(v[0], v[1], v[2]);
            out.append(reinterpret_cast<const char*>(colr.data()), colr.size());
            return;
        }
        for (double x : conv) real(out, x);
        return;
    }
    if (format_ == 'c') {
        Colr colr = toColr(c.r, c.g, c.b);
        out.append(reinterpret_cast<const char*>(colr.data()), colr.size());
        return;
    }
    real(out, c.r);
    real(out, c.g);
    real(out, c.b);
}

// RADIANCE compat (rtrace.c oputs/oputm/oputM): names are text followed by a tab in every
// output format; "*" when the ray hit nothing, "void" for the void modifier.
void RayWriter::name(std::string& out, int32_t index, bool hit) const {
    if (!hit)
        out += '*';
    else if (index < 0)
        out += "void";
    else if (scene_ && size_t(index) < scene_->prims.size())
        out += scene_->prims[size_t(index)].name;
    else
        out += std::to_string(index);
    out += '\t';
}

void RayWriter::record(std::string& out, const std::string& letters, const RayResult& r) const {
    const bool hit = r.hit;
    const bool named = hit || r.distantSource;  // RADIANCE's ro != NULL
    auto vec = [&](const Vec3& v, bool valid) {
        for (int k = 0; k < 3; ++k) real(out, valid ? v[k] : 0.0);
    };
    for (char c : letters) {
        switch (c) {
            case 'o':
                vec(r.origin, true);
                break;
            case 'd':
                vec(r.direction, true);
                break;
            case 'v':
                color(out, r.value, r.samples ? &r.samples->value : nullptr);
                break;
            case 'V': {  // contribution to the result
                std::vector<double> v;
                if (r.samples) {
                    v = r.samples->value;
                    for (size_t k = 0; k < v.size(); ++k) v[k] *= r.samples->coefficient[k];
                }
                color(out, r.value * r.coefficient, r.samples ? &v : nullptr);
                break;
            }
            case 'w':
                real(out, r.weight);
                break;
            case 'W':
                color(out, r.coefficient, r.samples ? &r.samples->coefficient : nullptr);
                break;
            case 'l':
                real(out, r.effectiveLength);
                break;
            case 'L':
                real(out, r.distance);
                break;
            case 'c':
                real(out, hit ? r.u : 0.0);
                real(out, hit ? r.v : 0.0);
                break;
            // RADIANCE compat (rtrace.c oputp, oputn, oputN): the ray origin for the point of
            // a ray that hit nothing, zero normals; a distant source's fields are its own.
            case 'p':
                vec(hit ? r.point : r.origin, true);
                break;
            case 'n':
                vec(r.normal, named);
                break;
            case 'N':
                vec(r.unperturbedNormal, named);
                break;
            case 's':
                name(out, r.prim, named && r.prim >= 0);
                break;
            case 'm':
                name(out, r.modifier, named);
                break;
            case 'M':
                name(out, r.material, named);
                break;
            case 'r':
                color(out, r.mirrored, r.samples ? &r.samples->mirrored : nullptr);
                break;
            case 'x':
                color(out, r.unmirrored, r.samples ? &r.samples->unmirrored : nullptr);
                break;
            case 'R':
                real(out, r.mirroredLength);
                break;
            case 'X':
                real(out, r.unmirroredLength);
                break;
            case '~':
                out += "~\t";
                break;
            default:
                break;
        }
    }
}

void RayWriter::write(std::string& out, const RayResult& r,
                      const std::vector<TracedRay>* tree) const {
    if (spec_.wantsTree() && tree) {
        // RADIANCE compat (rtrace.c ourtrace/tabin): one record per traced ray, indented
        // by one tab per ancestor, before the input ray's own record.
        for (const TracedRay& t : *tree) {
            if (!traced(t.result)) continue;
            out.append(size_t(std::max(0, t.depth)), '\t');
            record(out, spec_.tree, t.result);
            if (format_ == 'a') out += '\n';
        }
    }
    if (spec_.primary.empty()) return;
    record(out, spec_.primary, r);
    if (format_ == 'a') out += '\n';
}

void RayWriter::writeBogus(std::string& out) const {
    RayResult r;
    r.value = Color();
    r.coefficient = Color();
    r.weight = 0;
    r.distance = r.effectiveLength = r.mirroredLength = r.unmirroredLength = 0;
    if (spec_.primary.empty()) return;
    record(out, spec_.primary, r);
    if (format_ == 'a') out += '\n';
}

std::string rtraceHeader(const std::string& commandLine, char outputFormat, const OutputSpec& spec,
                         const ColourOutput& colours) {
    std::string h = "#?RADIANCE\n";
    h += commandLine + "\n";
    h += "SOFTWARE= radphoton\n";
    h += captureTimeLines();
    if (!colours.identity()) {
        // RADIANCE 6 (rtrace.c setrtoutput): values per record, none with the ray tree.
        int perRecord = 0, other = 0;
        for (char c : spec.primary) {
            if (std::string_view("vVWrx").find(c) != std::string_view::npos)
                ++perRecord;
            else if (std::string_view("odpnN").find(c) != std::string_view::npos)
                other += 3;
            else if (c == 'c')
                other += 2;
            else if (std::string_view("lLwRXsmM").find(c) != std::string_view::npos)
                ++other;
        }
        if (!spec.wantsTree()) h += colours.headerLines(perRecord, other);
    }
    h += "FORMAT=";
    h += outputFormat == 'a'        ? "ascii"
         : outputFormat == 'f'      ? "float"
         : outputFormat == 'd'      ? "double"
         : colours.components() > 3 ? "Radiance_spectra"  // a hyperspectral picture
                                    : "32-bit_rle_rgbe";
    h += "\n\n";
    return h;
}

std::string resolutionLine(int xres, int yres, bool padded) {
    if (padded) return paddedResolution(Resolution{xres, yres}) + "\n";
    return "-Y " + std::to_string(yres) + " +X " + std::to_string(xres) + "\n";
}

}  // namespace rp::render
