// genrev(1): surfaces of revolution (see genrev.h). Matches RADIANCE genrev.c's choice
// of primitive per segment, its naming, its %18.12g layout and its -s Phong records.
#include "gen/genrev.h"

#include <cmath>

#include "gen/gen_text.h"
#include "util/error.h"

namespace rp::gen {

namespace {

// genrev.c's own tolerance for "z (or r) did not change" (not RADIANCE's FTINY).
constexpr double kRevTiny = 1e-9;

const char* kUsage = "usage: genrev mat name 'z(t)' 'r(t)' nseg [-e expr][-f file][-s]";

// Unit normal of the profile segment (z0,r0) -> (z1,r1) in the (z, r) half plane: the
// segment direction turned by a right angle, so rising z gives an outward normal.
void profileNormal(double z0, double r0, double z1, double r1, double& nz, double& nr) {
    double dz = r0 - r1, dr = z1 - z0;
    double len = std::sqrt(dr * dr + dz * dz);
    // RADIANCE divides by zero here for a repeated point; such a segment is skipped, so
    // we give it no normal rather than NaNs that would leak into its neighbours' -s fits.
    if (len == 0) {
        nz = nr = 0;
        return;
    }
    nz = dz / len;
    nr = dr / len;
}

}  // namespace

GenrevOptions parseGenrevArgs(const std::vector<std::string>& args) {
    if (args.size() < 6) throw InputError(kUsage);
    GenrevOptions opt;
    opt.material = args[1];
    opt.name = args[2];
    opt.zExpr = args[3];
    opt.rExpr = args[4];
    opt.segments = parseInt(args[5], "nseg");
    if (opt.segments <= 0)
        throw InputError("nseg must be positive, got " + std::to_string(opt.segments));
    OptionTable table = genOptionTable();
    table.add(wordOption("-s", [&opt] { opt.smooth = true; }));
    addCalcOptions(table, opt.sources);
    std::vector<std::string> words = args;
    table.parseAll(words, 6);
    return opt;
}

std::vector<RevSegment> genrevSegments(const GenrevOptions& opt, GenFunctions& funcs) {
    GenFunctionId zf = funcs.define("z(t)", "t", opt.zExpr);
    GenFunctionId rf = funcs.define("r(t)", "t", opt.rExpr);
    funcs.build();
    const int nseg = opt.segments;
    auto radius = [&](double t) {
        double r = funcs.call(rf, t);
        if (r < 0)
            throw InputError(cformat("r(t) is negative (%g) at t = %g: radii must be >= 0", r, t));
        return r;
    };

    std::vector<RevSegment> out;
    double lastnz = 0, lastnr = 0;
    double t = 0;
    double lastz = funcs.call(zf, t), lastr = radius(t);
    t = 1.0 / nseg;
    double z = funcs.call(zf, t), r = radius(t);
    double nz, nr;
    profileNormal(lastz, lastr, z, r, nz, nr);
    for (int i = 1; i <= nseg; ++i) {
        double nextz = 0, nextr = 0, nextnz = 0, nextnr = 0;
        if (i < nseg) {
            t = double(i + 1) / nseg;
            nextz = funcs.call(zf, t);
            nextr = radius(t);
            profileNormal(z, r, nextz, nextr, nextnz, nextnr);
        }
        const bool down = z < lastz - kRevTiny, up = !down && z > lastz + kRevTiny;
        const bool in = r < lastr - kRevTiny, outw = !in && r > lastr + kRevTiny;
        if (up || down || in || outw) {
            RevSegment s;
            s.index = i;
            s.z0 = lastz;
            s.z1 = z;
            s.r0 = lastr;
            s.r1 = r;
            if (!(in || outw)) {
                s.kind = down ? RevSegment::Kind::Tube : RevSegment::Kind::Cylinder;
            } else if (!(up || down)) {
                s.kind = RevSegment::Kind::Ring;
                s.ringNormalZ = in ? 1.0 : -1.0;
            } else {
                s.kind = down ? RevSegment::Kind::Cup : RevSegment::Kind::Cone;
            }
            // RADIANCE compat (genrev.c -s): each normal component is fitted linearly
            // between the previous and the next segment's normals (0 beyond the ends),
            // the man page's BUGS note on the far side included.
            s.zLinear = up || down;
            if (s.zLinear) {
                double k = (nextnz - lastnz) / (z - lastz);
                s.phong[0] = k;
                s.phong[1] = lastnz - k * lastz;
            } else {
                s.phong[0] = 0;
                s.phong[1] = in ? 1 : -1;
            }
            s.rLinear = in || outw;
            if (s.rLinear) {
                double k = (nextnr - lastnr) / (r - lastr);
                s.phong[2] = k;
                s.phong[3] = lastnr - k * lastr;
            } else {
                s.phong[2] = 0;
                s.phong[3] = up ? 1 : -1;
            }
            out.push_back(s);
        }
        lastz = z;
        lastr = r;
        z = nextz;
        r = nextr;
        lastnz = nz;
        lastnr = nr;
        nz = nextnz;
        nr = nextnr;
    }
    return out;
}

std::string formatRevSegment(const GenrevOptions& opt, const RevSegment& s) {
    std::string out;
    std::string mod = opt.material;
    if (opt.smooth) {
        out += cformat("\n%s texfunc Phong\n4 rev_dx rev_dy rev_dz rev.cal\n0\n4\n",
                       opt.material.c_str());
        if (s.zLinear)
            out += cformat("\t%18.12g\t%18.12g\n", s.phong[0], s.phong[1]);
        else
            out += cformat("\t0\t%d\n", static_cast<int>(s.phong[1]));
        if (s.rLinear)
            out += cformat("\t%18.12g\t%18.12g\n", s.phong[2], s.phong[3]);
        else
            out += cformat("\t0\t%d\n", static_cast<int>(s.phong[3]));
        mod = "Phong";
    }
    const char* m = mod.c_str();
    const char* n = opt.name.c_str();
    switch (s.kind) {
        case RevSegment::Kind::Cylinder:
        case RevSegment::Kind::Tube:
            out += cformat("\n%s %s %s.%d\n0\n0\n7\n", m,
                           s.kind == RevSegment::Kind::Tube ? "tube" : "cylinder", n, s.index);
            out += cformat("\t0\t0\t%18.12g\n\t0\t0\t%18.12g\n\t%18.12g\n", s.z0, s.z1, s.r1);
            break;
        case RevSegment::Kind::Ring:
            // RADIANCE compat: the radii stay in profile order (outer first when r
            // shrinks); ring readers take the smaller as inner (geometry/ring.h).
            out += cformat("\n%s ring %s.%d\n0\n0\n8\n", m, n, s.index);
            out += cformat("\t0\t0\t%18.12g\n\t0\t0\t%18.12g\n\t%18.12g\t%18.12g\n", s.z1,
                           s.ringNormalZ, s.r0, s.r1);
            break;
        case RevSegment::Kind::Cone:
        case RevSegment::Kind::Cup:
            out += cformat("\n%s %s %s.%d\n0\n0\n8\n", m,
                           s.kind == RevSegment::Kind::Cup ? "cup" : "cone", n, s.index);
            out += cformat("\t0\t0\t%18.12g\n\t0\t0\t%18.12g\n\t%18.12g\t%18.12g\n", s.z0, s.z1,
                           s.r0, s.r1);
            break;
    }
    return out;
}

std::string genrev(const std::vector<std::string>& args, const std::vector<std::string>& searchPath,
                   std::vector<std::string>& warnings) {
    GenrevOptions opt = parseGenrevArgs(args);
    GenFunctions funcs(opt.sources, searchPath);
    std::vector<RevSegment> segs = genrevSegments(opt, funcs);
    std::string out = commandHeader(args);
    for (const RevSegment& s : segs) out += formatRevSegment(opt, s);
    if (std::string w = funcs.mathWarning(); !w.empty()) warnings.push_back(w);
    return out;
}

}  // namespace rp::gen
