// rfluxmtx's receivers and sender as its `#@rfluxmtx` lines and surfaces define them
// (RADIANCE rfluxmtx.c add_recv_object, add_send_object, finish_receiver,
// prepare_sampler): which settings belong to which surfaces, the basis orientation, and
// the checks that make a bad file one error line naming file and line.
#pragma once

#include <string>
#include <vector>

#include "flux/flux_params.h"
#include "flux/flux_scan.h"

namespace rp::flux {

// A receiver (one rcontrib modifier and its surfaces) or the sender, with its basis
// settled: `normal` the area-weighted mean of its surfaces' normals, `up` as set by u= or
// RADIANCE's default (+Z, or +Y for a normal within 45.6 degrees of Z).
struct FluxGroup {
    std::string modifier;
    SourceLoc loc;  // its first surface
    FluxParams params;
    BasisKind basis = BasisKind::Uniform;
    std::vector<FluxSurface> surfaces;
    Vec3 normal, up;
    // The sender's frame: u = up x normal (reversed for a left-handed basis), v = normal
    // x u. Unset for receivers, whose frame the .cal files build from normal and up.
    Vec3 uAxis, vAxis;
};

// The receivers of a scanned file, in order. A receiver takes the `#@rfluxmtx` lines
// read since the previous receiver began; h= carries over from one receiver to the next,
// u= and o= do not (RADIANCE). Throws InputError naming file and line: "missing receiver
// surface" (a file without polygon, ring or source), "missing hemisphere sampling type",
// "undefined normal for hemisphere sampling", "missing size for Shirley-Chiu sampling",
// "source 'name' must be 180-degrees" (but with h=u), "cannot mix source/non-source
// receivers", "duplicate receiver modifier 'm' (keep its surfaces together)".
std::vector<FluxGroup> receiversOf(const std::vector<ScanItem>& items, const std::string& file);

// The sender of a scanned file: every polygon and ring, each taking the lines read
// before it. Throws InputError naming file and line: "cannot use source as a sender",
// "no sender surface", "missing sender sampling type", "undefined normal for sender
// sampling", "up vector coincides with sender normal". Warns "multiple modifiers in
// sender" and "ignoring output file in sender ('spec')".
FluxGroup senderOf(const std::vector<ScanItem>& items, const std::string& file);

}  // namespace rp::flux
