// The getinfo program's logic: print the information header of RADIANCE files
// (pictures, octrees, scene files, photon maps), their dimensions (-d, +d), strip a
// header (-) or add lines to one (-a). tools/getinfo.cpp only wires up the streams.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace rp {

struct GetinfoOptions {
    enum class Mode {
        kHeader,      // getinfo [file ..]: headers
        kDimensions,  // getinfo -d [file ..]: "file: -Y N +X M" (octree, mesh: bounding cube)
        kBoth,        // getinfo +d [file ..]: header, then a tab and the dimensions
        kStrip,       // getinfo [-d] -: copy stdin without its header (and resolution, -d)
        kAppend,      // getinfo -a line ..: copy stdin with lines added to its header
    };
    Mode mode = Mode::kHeader;
    bool skipResolution = false;        // kStrip with -d
    std::vector<std::string> files;     // empty: standard input
    std::vector<std::string> addLines;  // kAppend
    // For -d on our scene files, which store records but no octree: "xmin ymin zmin
    // size" of the cube RADIANCE's oconv would give the scene (the tool supplies it; it
    // needs the geometry). Throws InputError. Unset: such a file is an error line.
    std::function<std::string(const std::string& path)> sceneCube;
};

// RADIANCE's argument order: an optional -d/+d first, then "-a line ..", "-" or files.
// Throws InputError for options getinfo does not have.
GetinfoOptions parseGetinfoArgs(int argc, const char* const* argv);

// Runs getinfo; error lines ("getinfo: x.txt: not a RADIANCE file", "getinfo: cannot
// open x") go to `err`, processing continues with the next file. Returns the exit
// status: 0 when every file was read, 1 otherwise.
int runGetinfo(const GetinfoOptions& opt, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace rp
