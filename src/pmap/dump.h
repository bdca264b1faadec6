// pmapdump's library (photon-map manual section 7): per-map option groups from the command
// line, random subsampling of a photon map, and the three writers (RADIANCE scene of glow
// spheres, ASCII "x y z r g b" point list, binary PLY point cloud). The tool's main only
// maps errors to exit codes; photon map files themselves are read by photon_map.h.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pmap/photon_map.h"

namespace rp::pmap {

// RADIANCE compat: pmapdump.c NSPHERES and RADCOEFF (sphere radius as a fraction of the
// estimated mean distance between spheres).
constexpr uint64_t kDumpDefaultCount = 10000;
constexpr double kDumpRadiusCoeff = 0.05;
// Seed of the subsampling streams; stream index = position of the map on the command line,
// so a map's sample does not depend on the other maps dumped with it.
constexpr uint64_t kDumpSeed = 0x706d6170;  // "pmap"

enum class DumpFormat { Scene, Ascii, Ply };

// One option group; reset to these defaults after each map (manual section 7).
struct DumpOptions {
    bool ascii = false;                          // -a[+|-]: ASCII point list
    bool ply = false;                            // -P[+|-]: binary PLY (beyond RADIANCE)
    uint64_t num = kDumpDefaultCount;            // -n num: target count (k/m suffixes)
    double radScale = 1.0;                       // -r radscale: sphere radius factor
    bool fluxColour = false;                     // -f[+|-]: colour by photon flux
    std::optional<std::array<float, 3>> colour;  // -c r g b: constant colour

    // -P wins over -a (both are point lists; -P is the one that cannot mix).
    DumpFormat format() const {
        return ply ? DumpFormat::Ply : ascii ? DumpFormat::Ascii : DumpFormat::Scene;
    }
};

struct DumpRequest {
    std::string path;
    DumpOptions options;
};

// Parses argv[1..argc-1] into one request per photon map file. Throws InputError (message
// without the "pmapdump: " prefix) for an unknown option, a missing or bad value (-n not a
// positive count, -r not > 0, -c not three non-negative numbers with a positive sum, a bad
// boolean suffix), -c together with -f for the same map, options after the last map, no
// map at all, and -P given for some maps but not all (a PLY file holds nothing else).
std::vector<DumpRequest> parseDumpArgs(int argc, const char* const* argv);

// RADIANCE compat: pmapdump.c colDefs, the default colour per photon type: global
// (0.25, 0.25, 2) blue, precomputed global (0.1, 1, 1) cyan, caustic (1, 0.1, 0.1) red,
// volume (0.1, 1, 0.1) green, direct (1, 0.1, 1) magenta, contribution (1, 1, 0.1) yellow.
std::array<float, 3> defaultDumpColour(PhotonMapType type);
// Suffix of RADIANCE's material and object names: "global", "pglobal", "caustic",
// "volume", "direct", "contrib" (mat.global, obj.global, ...).
const char* dumpObjectName(PhotonMapType type);

// RADIANCE compat: pmapdump.c. The distribution's dimension d counts the bounding box
// axes longer than FTINY (1e-6) and their product is its extent V; the radius is
// radScale * 0.05 * (V / num)^(1/d), num being the TARGET count (not min(num, photons), as
// RADIANCE). Beyond RADIANCE: a zero-extent box (d = 0, one photon or all coincident),
// where RADIANCE would write radius 0 or 0.05, gives radScale * 0.05 (unit extent).
double dumpSphereRadius(const PhotonMapStats& stats, uint64_t num, double radScale);

// RADIANCE compat: each photon is dumped with probability min(1, num / numPhotons), so the
// number written is only approximately num.
double dumpProbability(uint64_t num, uint64_t numPhotons);

struct DumpPoint {
    std::array<float, 3> pos;
    std::array<float, 3> colour;  // the map's constant colour, or scaled flux with -f
};

// The photons selected from one map, ready for a writer.
struct DumpedMap {
    std::string path;
    PhotonMapType type = PhotonMapType::Global;
    DumpOptions options;
    uint64_t numPhotons = 0;        // in the map
    double radius = 0;              // sphere radius (scene output)
    std::array<float, 3> colour{};  // constant colour (unused with -f)
    std::vector<DumpPoint> points;  // in file (kd-tree) order
};

// Selects photons with dumpProbability using Rng(seed, RngDomain::Sampling, mapIndex).
// With -f each point's colour is its flux times numPhotons / numSelected, so the dumped
// points carry the map's total flux. (RADIANCE scales by 1 / probability instead, which
// keeps the total only on average; the ratio is exact for equal-flux photons.)
DumpedMap sampleMap(const PhotonMap& map, const std::string& path, const DumpOptions& options,
                    uint64_t mapIndex, uint64_t seed = kDumpSeed);

// RADIANCE compat: pmapdump.c output. Scene: "# <command line>" and a blank line, then a
// "void glow mat.<type>" material (4 args: r g b 0) and one "mat.<type> sphere obj.<type>"
// per point, each followed by a blank line; with -f every sphere gets its own material
// (same name, redefined) before it. Numbers are printed with %g.
void writeDumpScene(std::ostream& out, const DumpedMap& map, const std::string& commandLine);
// One "x\ty\tz\tr\tg\tb" line per point, %g (switches to scientific notation as needed).
void writeDumpAscii(std::ostream& out, const DumpedMap& map);

// PLY colour bytes for a map's points (dump_ply.cpp). Constant colours are divided by
// max(1, largest component) so hue is kept (the default global blue (0.25, 0.25, 2)
// becomes (32, 32, 255)). Flux colours are tone-mapped linearly: divided by the 99th
// percentile of the per-point largest component, brighter points scaled down to keep their
// hue; no gamma. Returns that reference value (1 for constant colours).
double plyColourReference(const DumpedMap& map);
std::array<uint8_t, 3> plyColourBytes(const std::array<float, 3>& colour, double reference);

// One binary little-endian PLY ("element vertex N", float x y z, uchar red green blue)
// holding the points of all maps, with the command line and one line per map as comments.
void writeDumpPly(std::ostream& out, std::span<const DumpedMap> maps,
                  const std::string& commandLine);

// The whole tool: loads and samples every map first (so a bad or truncated map anywhere
// on the command line is reported before anything is written), then writes each map in
// its format to `out`, or one PLY for all. Throws InputError naming the file.
void runPmapdump(const std::vector<DumpRequest>& requests, const std::string& commandLine,
                 std::ostream& out);

}  // namespace rp::pmap
