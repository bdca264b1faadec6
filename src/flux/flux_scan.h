// Reading rfluxmtx's sender and receiver files as RADIANCE's rfluxmtx.c load_scene does:
// not a full scene parse, but a scan for `#@rfluxmtx` lines and the polygon, ring and
// source surfaces among the primitives (others are skipped by their argument counts),
// running `!command` lines for their output. Grouping the surfaces into receivers or a
// sender, and what the settings mean, is flux_surfaces.h's job.
#pragma once

#include <string>
#include <vector>

#include "util/error.h"
#include "util/vec.h"

namespace rp::flux {

enum class SurfaceType { Polygon, Ring, Source };

// One polygon, ring or source, with the normal and area rfluxmtx derives from it.
struct FluxSurface {
    SurfaceType type = SurfaceType::Polygon;
    std::string modifier, name;
    SourceLoc loc;
    std::vector<double> args;  // the real arguments; a ring's radii in increasing order
    Vec3 normal;               // unit; out of the front (a source: towards the sky it is seen from)
    // Polygon and ring: area. Source: projected solid angle of its cone, pi sin^2(a/2).
    double area = 0;
};

// What the scan met, in file order: a `#@rfluxmtx` line (its text after the keyword) or
// a surface.
struct ScanItem {
    bool isParams = false;
    std::string paramText;
    SourceLoc loc;
    FluxSurface surface;
};

// Scans `path` ("!command" runs the command). Throws InputError: "cannot load 'path'",
// and at the primitive "bad argument count for surface element 'name'", "bad orientation
// for surface element 'name'", "error reading arguments for 'name'". Surfaces without
// area are dropped with RADIANCE's warning "zero area for surface 'name'" (util/warnings).
std::vector<ScanItem> scanFluxFile(const std::string& path);

// The same for text already read; `file` names it in SourceLocs.
std::vector<ScanItem> scanFluxText(const std::string& text, const std::string& file);

}  // namespace rp::flux
