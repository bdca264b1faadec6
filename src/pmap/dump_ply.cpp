// pmapdump -P (beyond RADIANCE): all dumped photons as one binary little-endian PLY point
// cloud (Turk's PLY format as read by MeshLab, CloudCompare and Blender), with 8-bit
// colours tone-mapped from the photon colours. Scene and ASCII writers are in dump.cpp.
#include <algorithm>
#include <bit>
#include <cmath>
#include <ostream>

#include "pmap/dump.h"
#include "util/error.h"

namespace rp::pmap {
namespace {

// Percentile of the per-point largest flux component that maps to full intensity: a few
// very bright photons (caustics) must not leave everything else black.
constexpr double kFluxPercentile = 0.99;

float maxComponent(const std::array<float, 3>& c) { return std::max({c[0], c[1], c[2]}); }

void putFloatLE(std::string& out, float v) {
    const uint32_t u = std::bit_cast<uint32_t>(v);
    for (int s = 0; s < 32; s += 8) out.push_back(static_cast<char>((u >> s) & 0xff));
}

// PLY header lines must not break: file names and command lines lose any line breaks.
std::string oneLine(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

}  // namespace

double plyColourReference(const DumpedMap& map) {
    if (!map.options.fluxColour || map.points.empty()) return 1;
    std::vector<float> m;
    m.reserve(map.points.size());
    for (const DumpPoint& p : map.points) m.push_back(maxComponent(p.colour));
    const size_t k = std::min(m.size() - 1, size_t(kFluxPercentile * double(m.size() - 1) + 0.5));
    std::nth_element(m.begin(), m.begin() + std::ptrdiff_t(k), m.end());
    const double ref = m[k];
    // All-black (or percentile-black) maps: fall back to the brightest point.
    if (ref > 0) return ref;
    const double top = *std::max_element(m.begin(), m.end());
    return top > 0 ? top : 1;
}

std::array<uint8_t, 3> plyColourBytes(const std::array<float, 3>& colour, double reference) {
    RP_CHECK(reference > 0);
    std::array<double, 3> v{};
    double top = 0;
    for (size_t c = 0; c < 3; ++c) {
        v[c] = std::max(0.0, double(colour[c]) / reference);
        top = std::max(top, v[c]);
    }
    const double scale = top > 1 ? 1 / top : 1;  // keep hue when clipping
    std::array<uint8_t, 3> b{};
    for (size_t c = 0; c < 3; ++c)
        b[c] = static_cast<uint8_t>(std::lround(std::min(255.0, 255 * v[c] * scale)));
    return b;
}

void writeDumpPly(std::ostream& out, std::span<const DumpedMap> maps,
                  const std::string& commandLine) {
    size_t total = 0;
    for (const DumpedMap& m : maps) total += m.points.size();

    std::string text = "ply\nformat binary_little_endian 1.0\n";
    text += "comment " + oneLine(commandLine) + "\n";
    std::vector<double> refs;
    for (const DumpedMap& m : maps) {
        refs.push_back(plyColourReference(m));
        text += "comment " + oneLine(m.path) + ": " + photonMapTypeName(m.type) + " photon map, " +
                std::to_string(m.points.size()) + " of " + std::to_string(m.numPhotons) +
                " photons";
        if (m.options.fluxColour) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "%g", refs.back());
            text += ", flux colours, 255 = " + std::string(buf) + " W";
        }
        text += "\n";
    }
    text += "element vertex " + std::to_string(total) + "\n";
    text += "property float x\nproperty float y\nproperty float z\n";
    text += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    text += "end_header\n";

    for (size_t i = 0; i < maps.size(); ++i) {
        for (const DumpPoint& p : maps[i].points) {
            for (float x : p.pos) putFloatLE(text, x);
            for (uint8_t c : plyColourBytes(p.colour, refs[i]))
                text.push_back(static_cast<char>(c));
            if (text.size() > (1u << 16)) {
                out.write(text.data(), std::streamsize(text.size()));
                text.clear();
            }
        }
    }
    out.write(text.data(), std::streamsize(text.size()));
}

}  // namespace rp::pmap
