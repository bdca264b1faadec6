// rtrace's ray input and result output (RADIANCE rtrace.c getvec/printvals/oput*): the -o
// specifier list, reading origin/direction records in -fa/-ff/-fd, and formatting one ray's
// RayResult (and its ray tree) in -fa/-ff/-fd/-fc. The batch driver is in rtrace_run.h.
#pragma once

#include <cstdint>
#include <istream>
#include <string>
#include <unordered_set>
#include <vector>

#include "render/colour_output.h"
#include "render/renderer.h"
#include "render/rtrace_options.h"
#include "scene/primitive.h"
#include "util/vec.h"

namespace rp::render {

// -o spec: letters before a 't' or 'T' are printed for each input ray; letters after it for
// every ray of the ray tree (RADIANCE rtrace.1: "t", "T" also traces rays to sources).
struct OutputSpec {
    std::string primary;
    std::string tree;
    bool traceSources = false;  // 'T'
    bool wantsTree() const { return !tree.empty(); }
};

// Throws InputError for a letter rtrace does not know, and with format 'c' for a letter
// that is not a colour (v V W r x: RADIANCE writes those as 4-byte RGBE).
OutputSpec parseOutputSpec(const std::string& spec, char outputFormat);

struct InputRay {
    Vec3 origin, direction;  // as read (direction not normalised)
};

// Reads rays: 6 numbers each, ASCII words or native-endian float/double.
class RayReader {
public:
    enum class Status { Ok, End, Bad };
    RayReader(std::istream& in, char format) : in_(in), format_(format) {}

    // End: clean end of input. Bad: ASCII text that is not a number or a record cut short;
    // error() says what and where ("bad ray at input line 3: 'abc' is not a number").
    Status next(InputRay& ray);
    const std::string& error() const { return error_; }
    long line() const { return line_; }      // current input line (ASCII)
    uint64_t rays() const { return rays_; }  // records read so far

private:
    bool word(std::string& w);  // next white-space separated word (ASCII); counts lines
    std::istream& in_;
    char format_;
    long line_ = 1;
    long wordLine_ = 1;
    uint64_t rays_ = 0;
    std::string error_;
};

// Formats results for one output spec and format (RADIANCE oput* functions).
class RayWriter {
public:
    // `scene` (may be null: names print as "*" / indices) names surfaces, modifiers and
    // materials for s, m, M.
    // `colours`: how colour values are printed (resolved for the run's sampling).
    RayWriter(OutputSpec spec, char format, const Scene* scene, ColourOutput colours = {});

    // -ti/-te: with a list, the tree records are only those of rays that hit a surface
    // whose modifier is listed (-ti), or all but those (-te; rays that hit nothing are
    // reported), as RADIANCE's ourtrace. The input ray's own record is always written.
    void setTraceFilter(const TraceFilter& filter);

    // Appends the tree records (if requested) then the ray's own record.
    void write(std::string& out, const RayResult& r, const std::vector<TracedRay>* tree) const;
    // RADIANCE's bogus record (zero direction or unusable input): every value zero.
    void writeBogus(std::string& out) const;

    const OutputSpec& spec() const { return spec_; }

private:
    void record(std::string& out, const std::string& letters, const RayResult& r) const;
    void real(std::string& out, double v) const;
    // A colour result: its samples when the ray was rendered in passes, else c.
    void color(std::string& out, const Color& c, const std::vector<double>* samples) const;
    void name(std::string& out, int32_t index, bool hit) const;
    bool traced(const RayResult& r) const;  // passes the trace filter
    OutputSpec spec_;
    TraceFilter::Mode traceMode_ = TraceFilter::Mode::kAll;
    std::unordered_set<std::string> traceModifiers_;
    char format_;
    const Scene* scene_;
    ColourOutput colours_;
};

// The header rtrace writes with -h+: the command line up to the scene file, SOFTWARE,
// CAPDATE/GMT (RADIANCE fputnow) and FORMAT; the empty line ends it.
// With colour options beyond RGB (colours.identity() false) RADIANCE 6's NCOMP= and the
// lines of ColourOutput::headerLines come before FORMAT=.
std::string rtraceHeader(const std::string& commandLine, char outputFormat,
                         const OutputSpec& spec = {}, const ColourOutput& colours = {});

// "-Y y +X x\n" (RADIANCE fprtresolu, standard orientation); `padded`: sizes in 8
// columns, as RADIANCE 6 writes them (hyperspectral pictures).
std::string resolutionLine(int xres, int yres, bool padded = false);

}  // namespace rp::render
