// Setting up and running rfluxmtx's rcontrib (see rfluxmtx.h).
#include "flux/rfluxmtx.h"

#include <optional>
#include <set>

#include "flux/basis.h"
#include "flux/flux_scan.h"
#include "flux/sender_rays.h"
#include "render/rcontrib.h"
#include "util/header.h"

namespace rp::flux {

namespace {

// RADIANCE's rfluxmtx is seeded from the clock; ours repeats its rays run to run.
constexpr uint64_t kSenderSeed = 0x72666c75786d7478ULL;  // "rfluxmtx"

// One receiver's rcontrib options in RADIANCE's order (rfluxmtx.c finish_receiver): -o,
// the .cal file once per run, -p, -bn, -b, then -m. Returns the receiver's bin count.
int addReceiverArgs(const FluxGroup& r, std::set<std::string>& calFiles,
                    std::vector<std::string>& args) {
    const ReceiverBins b = receiverBins(r.basis, r.params.size, r.params.sign, r.normal, r.up);
    if (r.params.outSpec) args.insert(args.end(), {"-o", *r.params.outSpec});
    if (!b.calFile.empty() && calFiles.insert(b.calFile).second)
        args.insert(args.end(), {"-f", b.calFile});
    if (!b.params.empty()) args.insert(args.end(), {"-p", b.params});
    args.insert(args.end(), {"-bn", b.countExpr, "-b", b.binExpr, "-m", r.modifier});
    return b.bins;
}

// A word as a shell would need it on oconv's command line (RADIANCE's SPECIALS).
std::string shellWord(const std::string& w) {
    if (w.find_first_of(" \t\n'\"()${}*?[];|&") == std::string::npos) return w;
    return "'" + w + "'";
}

// The scene RADIANCE's `oconv -f [-w] system... receiver` would compile: -i's octree,
// the system files, the receiver file last; the octree's header line is oconv's
// command line.
render::RcontribScene sceneOf(const RfluxmtxCommand& cmd, const LoadOptions& load,
                              std::string& oconvCommand) {
    render::RcontribScene scene;
    scene.load = load;
    std::vector<std::string> words = {"oconv", "-f"};
    if (!cmd.warnings) words.push_back("-w");
    std::vector<std::string> files;
    for (size_t i = 0; i < cmd.systemArgs.size(); ++i) {
        const std::string& w = cmd.systemArgs[i];
        words.push_back(w);
        if (w == "-i" && i + 1 < cmd.systemArgs.size()) {
            scene.files.push_back(cmd.systemArgs[++i]);  // the octree comes first
            words.push_back(scene.files.back());
        } else if (w.size() > 1 && w[0] == '-') {
            throw InputError("unsupported system argument '" + w + "'; " +
                             rfluxmtxUsage("rfluxmtx"));
        } else {
            files.push_back(w);
        }
    }
    words.push_back(cmd.receiverFile);
    files.push_back(cmd.receiverFile);
    scene.files.insert(scene.files.end(), files.begin(), files.end());
    std::vector<const char*> argv;
    oconvCommand = "!";
    for (const std::string& w : words) {
        argv.push_back(w.c_str());
        oconvCommand += (argv.size() > 1 ? " " : "") + shellWord(w);
    }
    scene.headerLines = {commandLine(int(argv.size()), argv.data())};
    return scene;
}

// -bn is parsed here only to fill the options; the counts come from the bases.
double anyBinCount(const std::vector<render::CalcDefinition>&, const std::string&) { return 1; }

}  // namespace

RfluxmtxSetup setupRfluxmtx(const RfluxmtxCommand& cmd, const LoadOptions& load) {
    RfluxmtxSetup s;
    s.receivers = receiversOf(scanFluxFile(cmd.receiverFile), cmd.receiverFile);
    std::vector<std::string> args = cmd.rcontribArgs;
    std::set<std::string> calFiles;
    std::vector<int> bins;
    for (const FluxGroup& r : s.receivers) bins.push_back(addReceiverArgs(r, calFiles, args));
    if (!cmd.senderFile.empty()) {
        s.sender = senderOf(scanFluxFile(cmd.senderFile), cmd.senderFile);
        args.insert(args.end(),
                    {"-y", std::to_string(basisBins(s.sender->basis, s.sender->params.size))});
    }
    std::string oconv;
    s.scene = sceneOf(cmd, load, oconv);
    args.push_back(oconv);
    s.commandLine = args;
    s.options = render::parseRcontribArgs(args, &anyBinCount);
    for (size_t i = 0; i < s.options.modifiers.size() && i < bins.size(); ++i)
        s.options.modifiers[i].bins = bins[i];
    return s;
}

void runRfluxmtx(const RfluxmtxCommand& cmd, const LoadOptions& load, std::istream& in,
                 std::ostream& out, std::ostream& diag, Cluster& cluster) {
    const RfluxmtxSetup s = setupRfluxmtx(cmd, load);
    if (cmd.verbose) {
        std::vector<const char*> argv;
        for (const std::string& w : s.commandLine) argv.push_back(w.c_str());
        diag << "rfluxmtx: running: " << commandLine(int(argv.size()), argv.data()) << '\n';
    }
    if (!s.sender) {
        render::runRcontribTool(s.options, s.scene, in, out, cluster);
        return;
    }
    SenderRayBuffer buffer(*s.sender, cmd.samples, kSenderSeed);
    if (cmd.verbose) {
        diag << "rfluxmtx: sampling " << buffer.bins() << " directions";
        if (s.sender->surfaces.size() > 1)
            diag << " (" << s.sender->surfaces.size() << " elements)";
        diag << '\n';
    }
    std::istream rays(&buffer);
    try {
        render::runRcontribTool(s.options, s.scene, rays, out, cluster);
    } catch (...) {
        if (buffer.error()) std::rethrow_exception(buffer.error());
        throw;
    }
    if (buffer.error()) std::rethrow_exception(buffer.error());
}

}  // namespace rp::flux
