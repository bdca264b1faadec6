// pmapdump: default colours, sphere radius, random subsampling, the RADIANCE scene and
// ASCII point list writers, and the whole run (the PLY writer is in dump_ply.cpp).
#include "pmap/dump.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "util/error.h"
#include "util/rng.h"

namespace rp::pmap {
namespace {

// RADIANCE compat: FTINY for double RREAL (fvect.h); bounding box axes shorter than this do
// not count as a dimension of the photon distribution.
constexpr double kFtiny = 1e-6;

// printf into a small buffer and append to `out`; %g output of 4 to 6 numbers fits easily.
template <typename... Args>
void appendf(std::string& out, const char* fmt, Args... args) {
    char buf[256];
    const int n = std::snprintf(buf, sizeof buf, fmt, args...);
    RP_CHECK(n >= 0 && size_t(n) < sizeof buf);
    out.append(buf, size_t(n));
}

void appendMaterial(std::string& out, const char* name, const std::array<float, 3>& c) {
    appendf(out, "void glow mat.%s\n0\n0\n4 %g %g %g 0\n\n", name, double(c[0]), double(c[1]),
            double(c[2]));
}

}  // namespace

std::array<float, 3> defaultDumpColour(PhotonMapType type) {
    switch (type) {
        case PhotonMapType::Global:
            return {0.25f, 0.25f, 2.0f};
        case PhotonMapType::PreComp:
            return {0.1f, 1.0f, 1.0f};
        case PhotonMapType::Caustic:
            return {1.0f, 0.1f, 0.1f};
        case PhotonMapType::Volume:
            return {0.1f, 1.0f, 0.1f};
        case PhotonMapType::Direct:
            return {1.0f, 0.1f, 1.0f};
        case PhotonMapType::Contrib:
        case PhotonMapType::PreCompContrib:
            return {1.0f, 1.0f, 0.1f};
    }
    RP_CHECK(false);
    return {};
}

const char* dumpObjectName(PhotonMapType type) {
    switch (type) {
        case PhotonMapType::Global:
            return "global";
        case PhotonMapType::PreComp:
            return "pglobal";
        case PhotonMapType::Caustic:
            return "caustic";
        case PhotonMapType::Volume:
            return "volume";
        case PhotonMapType::Direct:
            return "direct";
        case PhotonMapType::Contrib:
            return "contrib";
        case PhotonMapType::PreCompContrib:
            return "pcontrib";
    }
    RP_CHECK(false);
    return "";
}

double dumpSphereRadius(const PhotonMapStats& stats, uint64_t num, double radScale) {
    RP_CHECK(num > 0);
    double extent = 1;
    int dim = 0;
    for (size_t a = 0; a < 3; ++a) {
        const double side = double(stats.bboxMax[a]) - double(stats.bboxMin[a]);
        if (side > kFtiny) {
            ++dim;
            extent *= side;
        }
    }
    if (dim == 0) return radScale * kDumpRadiusCoeff;
    return radScale * kDumpRadiusCoeff * std::pow(extent / double(num), 1.0 / dim);
}

double dumpProbability(uint64_t num, uint64_t numPhotons) {
    if (numPhotons == 0 || num >= numPhotons) return 1;
    return double(num) / double(numPhotons);
}

DumpedMap sampleMap(const PhotonMap& map, const std::string& path, const DumpOptions& options,
                    uint64_t mapIndex, uint64_t seed) {
    DumpedMap d;
    d.path = path;
    d.type = map.type();
    d.options = options;
    d.numPhotons = map.size();
    d.radius = dumpSphereRadius(map.stats(), options.num, options.radScale);
    d.colour = options.colour ? *options.colour : defaultDumpColour(map.type());

    const double prob = dumpProbability(options.num, map.size());
    Rng rng(seed, RngDomain::Sampling, mapIndex);
    std::vector<const Photon*> selected;
    selected.reserve(size_t(prob * double(map.size()) * 1.1) + 16);
    for (const Photon& p : map.photons())
        if (prob >= 1 || rng.uniform() < prob) selected.push_back(&p);

    // Manual section 7: -f flux is adjusted for the dumped fraction to keep the total flux.
    const double fluxScale = selected.empty() ? 1.0 : double(map.size()) / double(selected.size());
    d.points.reserve(selected.size());
    for (const Photon* p : selected) {
        DumpPoint pt{{p->pos[0], p->pos[1], p->pos[2]}, d.colour};
        if (options.fluxColour) {
            const std::array<float, 3> f = p->fluxRgb();
            for (size_t c = 0; c < 3; ++c) pt.colour[c] = static_cast<float>(f[c] * fluxScale);
        }
        d.points.push_back(pt);
    }
    return d;
}

void writeDumpScene(std::ostream& out, const DumpedMap& map, const std::string& commandLine) {
    const char* name = dumpObjectName(map.type);
    std::string text = "# " + commandLine + "\n\n";
    if (!map.options.fluxColour) appendMaterial(text, name, map.colour);
    for (const DumpPoint& p : map.points) {
        if (map.options.fluxColour) appendMaterial(text, name, p.colour);
        appendf(text, "mat.%s sphere obj.%s\n0\n0\n4 %g %g %g %g\n\n", name, name, double(p.pos[0]),
                double(p.pos[1]), double(p.pos[2]), map.radius);
        if (text.size() > (1u << 16)) {
            out << text;
            text.clear();
        }
    }
    out << text;
}

void writeDumpAscii(std::ostream& out, const DumpedMap& map) {
    std::string text;
    for (const DumpPoint& p : map.points) {
        appendf(text, "%g\t%g\t%g\t%g\t%g\t%g\n", double(p.pos[0]), double(p.pos[1]),
                double(p.pos[2]), double(p.colour[0]), double(p.colour[1]), double(p.colour[2]));
        if (text.size() > (1u << 16)) {
            out << text;
            text.clear();
        }
    }
    out << text;
}

void runPmapdump(const std::vector<DumpRequest>& requests, const std::string& commandLine,
                 std::ostream& out) {
    // Load and sample everything first: a bad map anywhere means no output at all (RADIANCE
    // writes the earlier maps, then fails). Only the samples are kept, not the maps.
    std::vector<DumpedMap> dumped;
    dumped.reserve(requests.size());
    for (size_t i = 0; i < requests.size(); ++i) {
        const PhotonMap map = PhotonMap::load(requests[i].path);
        dumped.push_back(sampleMap(map, requests[i].path, requests[i].options, i));
    }
    // parseDumpArgs ensures -P is all or nothing.
    if (!dumped.empty() && dumped.front().options.format() == DumpFormat::Ply) {
        writeDumpPly(out, dumped, commandLine);
    } else {
        for (const DumpedMap& d : dumped) {
            RP_CHECK(d.options.format() != DumpFormat::Ply);
            if (d.options.format() == DumpFormat::Ascii)
                writeDumpAscii(out, d);
            else
                writeDumpScene(out, d, commandLine);
        }
    }
    out.flush();
    if (!out) throw InputError("error writing output (disk full or closed pipe?)");
}

}  // namespace rp::pmap
