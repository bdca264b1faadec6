// objview: a quick look at RADIANCE objects, as RADIANCE's objview(1) gives it: the
// inputs (or a scene on standard input, e.g. `pmapdump map.pm | objview`) with three
// distant lights and a dim glow around them, seen from a standard view around their
// bounding cube ("XYZ": from +X+Y+Z, up +Z) through rad in our rvu. Beyond RADIANCE's:
// -r picture renders that view to a picture file instead (rad's rpict and pfilt), and
// -ap file [bwidth] passes photon maps to the renderer.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "rad/rad_run.h"

namespace rp::rad {

struct ObjviewCommand {
    std::string up = "Z";                 // -u
    std::string view = "XYZ";             // -v: a standard view
    std::string device = "x11";           // -o (our rvu shows any window device in a browser)
    std::string renderOptions;            // -b: " -bv"; -ap file [bwidth]
    std::vector<std::string> radOptions;  // -s -w -V -e, -N n
    std::string picture;                  // -r: render to this picture instead of rvu
    std::vector<std::string> inputs;      // empty: standard input
};

// objview [-u up][-v view][-b][-s][-w][-V][-e][-n|-N nprocs][-o dev][-r picture]
//         [-ap file [bwidth]] [input ..]; -g (glrad) is refused. Throws InputError.
ObjviewCommand parseObjviewArgs(const std::vector<std::string>& args);

// Writes the lights and the RIF into a temporary folder, runs rad there (with `shell`
// for its commands) and, with -r, moves the picture to its place. Standard input is
// read when there are no inputs.
void runObjview(const ObjviewCommand& cmd, std::istream& in, std::ostream& out, const Shell& shell);

}  // namespace rp::rad
