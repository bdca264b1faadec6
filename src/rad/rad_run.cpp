// rad's executive (see rad_run.h): RADIANCE 5.4 rad.c's main, checkfiles, setdefaults,
// getoctcube, oconv, mkpmap, checkambfile, rvu and rpict, with its commands and order.
#include "rad/rad_run.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <mutex>
#include <ostream>
#include <random>
#include <thread>

#include "gen/builtin_commands.h"
#include "image/view.h"
#include "rad/rad_settings.h"
#include "rad/rif.h"
#include "scene/scene_bbox.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"
#include "util/warnings.h"

namespace rp::rad {

namespace {

// File dates in seconds with their fractions: two tools run within one second still
// order (RADIANCE compares whole seconds).
using Date = double;

Date fileDate(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return 0;
    return double(st.st_mtim.tv_sec) + 1e-9 * double(st.st_mtim.tv_nsec);
}

Date now() {
    timespec ts{};
    clock_gettime(CLOCK_REALTIME, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// RADIANCE's rootname: the RIF's name without its suffix.
std::string rootName(const std::string& rif) {
    const std::size_t slash = rif.rfind('/');
    const std::size_t dot = rif.rfind('.');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
        return rif.substr(0, dot);
    return rif;
}

// RADIANCE's newfname: `pred` inserted before the suffix ("inst.oct" -> "inst0.oct").
std::string insertBeforeSuffix(const std::string& name, char pred) {
    const std::size_t slash = name.rfind('/');
    std::size_t dot = name.rfind('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) dot = name.size();
    return name.substr(0, dot) + pred + name.substr(dot);
}

// A name for mkillum's output that no file has (RADIANCE's mktemp "ilXXXXXX").
std::string temporaryName(bool create) {
    std::string name = "ilXXXXXX";
    if (create) {
        const int fd = ::mkstemp(name.data());
        if (fd >= 0) {
            ::close(fd);
            return name;
        }
    }
    static const char kChars[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    std::random_device rd;
    for (std::size_t i = 2; i < name.size(); ++i) name[i] = kChars[rd() % (sizeof kChars - 1)];
    return name;
}

class Executive {
public:
    Executive(const RadCommand& cmd, std::ostream& out, const Shell& shell)
        : cmd_(cmd), nprocs_(cmd.nprocs), out_(out), shell_(shell) {}
    void run();

private:
    void loadVariables();
    void checkFiles();
    Date lastDate(Var v) const;
    void setDefaults();
    double cubeSize();
    double cubeFromSceneFiles();
    double cubeFromOctree();
    void buildOctrees();
    void buildIlluminated(const std::string& ocopts);
    void makePhotonMaps();
    void checkAmbientFile();
    std::string transferOptions(const std::string& render);
    void runRvu(const std::string& render, const std::string& picture);
    void runRpict(const std::string& render, const std::string& picture);
    struct ViewJob;
    void renderView(const ViewJob& job, const std::string& view, const std::string& name);
    void renderViews(const ViewJob& job,
                     const std::vector<std::pair<std::string, std::string>>& views);
    void printView(const std::string& view);

    // RADIANCE's runcom, touch, rmfile, mvfile: echo unless -s, act unless -n.
    bool runCommand(const std::string& command);
    void touch(const std::string& file);
    void removeFile(const std::string& file);
    void moveFile(const std::string& from, const std::string& to);
    void echo(const std::string& line);
    [[noreturn]] void fail(const std::string& message) const { throw InputError(message); }

    const RadCommand& cmd_;
    int nprocs_;
    std::ostream& out_;
    const Shell& shell_;
    std::mutex outMutex_;
    RifVars vars_;
    Programs programs_;
    std::string radName_;
    std::string oct0Name_, oct1Name_;
    std::string pgmapName_, pcmapName_;
    Date sceneDate_ = 0, octreeDate_ = 0, matDate_ = 0, illumDate_ = 0;
    Date oct0Date_ = 0, oct1Date_ = 0, pgmapDate_ = 0, pcmapDate_ = 0;
    double cubeSize_ = 0;
    double cubeOrg_[3] = {0, 0, 0};
    bool overture_ = false;
};

void Executive::echo(const std::string& line) {
    if (cmd_.silent) return;
    std::lock_guard<std::mutex> lock(outMutex_);
    out_ << '\t' << line << '\n';
}

bool Executive::runCommand(const std::string& command) {
    echo(command);
    if (!nprocs_) return true;
    {
        std::lock_guard<std::mutex> lock(outMutex_);
        out_.flush();
        std::fflush(nullptr);
    }
    return shell_(command) == 0;
}

void Executive::touch(const std::string& file) {
    echo("touch " + file);
    if (nprocs_) ::utimensat(AT_FDCWD, file.c_str(), nullptr, 0);
}

void Executive::removeFile(const std::string& file) {
    echo("rm -f " + file);
    if (nprocs_) std::remove(file.c_str());
}

void Executive::moveFile(const std::string& from, const std::string& to) {
    echo("mv " + from + " " + to);
    if (nprocs_) std::rename(from.c_str(), to.c_str());
}

void Executive::loadVariables() {
    radName_ = rootName(cmd_.rifFile);
    vars_.load(cmd_.rifFile);
    for (const std::string& a : cmd_.assignments)
        if (!vars_.assign(a, SourceLoc{})) throw InputError("unknown variable: " + a);
    vars_.check(!cmd_.noWarnings);
}

// RADIANCE's checklast: the latest date of the files in a list ("!command" words count
// as dated 1, older than any file); a missing file is an error.
Date Executive::lastDate(Var v) const {
    Date last = 0;
    for (const Assignment& a : vars_.assignments(v)) {
        for (const std::string& f : valueWords(a.value)) {
            if (f[0] == '!' || (f[0] == '\\' && f.size() > 1 && f[1] == '!')) {
                if (!last) last = 1;
                continue;
            }
            const Date d = fileDate(f);
            if (!d)
                throw InputError(a.loc,
                                 "cannot find " + std::string(info(v).name) + " file '" + f + "'");
            last = std::max(last, d);
        }
    }
    return last;
}

void Executive::checkFiles() {
    if (!vars_.defined(Var::kOctree))
        vars_.setDefault(Var::kOctree, radName_ + ".oct");
    else if (vars_.value(Var::kOctree)[0] == '!')
        throw InputError(vars_.where(Var::kOctree), "illegal 'OCTREE' specification");
    const std::string& oct = vars_.value(Var::kOctree);
    octreeDate_ = fileDate(oct);
    if (vars_.defined(Var::kIllum)) {  // illum needs the secondary octrees
        oct0Name_ = insertBeforeSuffix(oct, '0');
        oct1Name_ = insertBeforeSuffix(oct, '1');
        oct0Date_ = fileDate(oct0Name_);
        oct1Date_ = fileDate(oct1Name_);
    } else {
        oct0Name_ = oct1Name_ = oct;
    }
    if ((sceneDate_ = lastDate(Var::kScene)) != 0)
        sceneDate_ = std::max(sceneDate_, lastDate(Var::kObject));
    illumDate_ = lastDate(Var::kIllum);
    if (!octreeDate_ && !sceneDate_ && !illumDate_) fail("need 'OCTREE' or 'scene' or 'illum'");
    for (Var v : {Var::kPgmap, Var::kPcmap}) {
        if (!vars_.defined(v)) continue;
        const std::vector<std::string> w = valueWords(vars_.value(v));
        if (w.size() < 2)
            throw InputError(vars_.where(v),
                             std::string("'") + info(v).name + "' missing # photons argument");
        (v == Var::kPgmap ? pgmapName_ : pcmapName_) = w[0];
        (v == Var::kPgmap ? pgmapDate_ : pcmapDate_) = fileDate(w[0]);
    }
    matDate_ = lastDate(Var::kMaterial);
}

void Executive::setDefaults() {
    if (!vars_.defined(Var::kZone)) {
        const double size = cubeSize();
        vars_.setDefault(Var::kZone, formatLine("E %g %g %g %g %g %g", cubeOrg_[0],
                                                cubeOrg_[0] + size, cubeOrg_[1], cubeOrg_[1] + size,
                                                cubeOrg_[2], cubeOrg_[2] + size));
    }
    if (!vars_.defined(Var::kEyeSep)) {
        const Zone z = zoneOf(vars_);
        vars_.setDefault(Var::kEyeSep, formatLine("%f", 0.01 * (z.max[0] - z.min[0] + z.max[1] -
                                                                z.min[1] + z.max[2] - z.min[2])));
    }
    vars_.setDefault(Var::kIndirect, "0");
    vars_.setDefault(Var::kQuality, "L");
    vars_.setDefault(Var::kResolution, "512");
    vars_.setDefault(Var::kPicture, radName_);
    vars_.setDefault(Var::kViews, "X");
    vars_.setDefault(Var::kDetail, "M");
    vars_.setDefault(Var::kPenumbras, "F");
    vars_.setDefault(Var::kVariability, "L");
}

// RADIANCE's getoctcube: the scene's bounding cube, from getbbox's numbers while only
// printing and the octree is out of date, else from the (built) octree.
double Executive::cubeSize() {
    if (cubeSize_ > 1e-6) return cubeSize_;
    if (!nprocs_ && fileDate(oct1Name_) < std::max(sceneDate_, illumDate_))
        cubeSize_ = cubeFromSceneFiles();
    else
        cubeSize_ = cubeFromOctree();
    return cubeSize_;
}

// "getbbox -w -h scene": the box printed in %9g, read back, made a cube.
double Executive::cubeFromSceneFiles() {
    const Var v = vars_.defined(Var::kScene) ? Var::kScene : Var::kIllum;
    const QuietWarnings quiet;  // getbbox -w
    const BoundingBox box = sceneBoundingBox(valueWords(vars_.value(v)), gen::builtinLoadOptions());
    double min[3], max[3];
    if (std::sscanf(formatBoundingBox(box, false).c_str(), "%lf %lf %lf %lf %lf %lf", &min[0],
                    &max[0], &min[1], &max[1], &min[2], &max[2]) != 6)
        fail("error reading bounding box from getbbox");
    double size = 0;
    for (int i = 0; i < 3; ++i) size = std::max(size, max[i] - min[i]);
    for (int i = 0; i < 3; ++i) cubeOrg_[i] = (max[i] + min[i] - size) * .5;
    return size;
}

// "getinfo -d < octree": the cube stored after the octree's header.
double Executive::cubeFromOctree() {
    buildOctrees();  // nothing if done
    std::ifstream in(oct1Name_, std::ios::binary);
    if (!in) throw InputError(SourceLoc{oct1Name_, 0}, "cannot open octree");
    readHeader(in, oct1Name_);
    std::string text;
    if (in.get() == 1) {
        in.get();
        int strings = 0;
        for (int c; (c = in.get()) != EOF && strings < 4;) {
            if (c == 0) ++strings;
            text.push_back(c == 0 ? ' ' : char(c));
        }
    }
    double size = 0;
    if (std::sscanf(text.c_str(), "%lf %lf %lf %lf", &cubeOrg_[0], &cubeOrg_[1], &cubeOrg_[2],
                    &size) != 4)
        throw InputError(SourceLoc{oct1Name_, 0}, "error reading bounding cube from getinfo");
    return size;
}

// RADIANCE's oconv(): the octree from materials and scene; with illum files the octree
// with them (NAME0.oct), mkillum's sources, and the frozen NAME1.oct.
void Executive::buildOctrees() {
    const std::string ocopts = toolOptions(vars_, Var::kOconv, programs_.oconv);
    const std::string& oct = vars_.value(Var::kOctree);
    const std::string mat = vars_.defined(Var::kMaterial) ? " " + vars_.value(Var::kMaterial) : "";
    if (octreeDate_ < sceneDate_) {
        if (cmd_.touchOnly && octreeDate_) {
            touch(oct);
        } else if (!runCommand(programs_.oconv + ocopts + mat + " " + vars_.value(Var::kScene) +
                               " > " + oct)) {
            std::remove(oct.c_str());
            fail("error generating octree (" + oct + " removed)");
        }
        octreeDate_ = std::max(now(), sceneDate_);
    }
    // RADIANCE sets the date again on the second call (from getoctcube), losing a newer
    // photon map's date, so the pictures were not made again with the new map.
    if (oct1Name_ == oct) oct1Date_ = std::max({oct1Date_, octreeDate_, matDate_});
    if (oct1Date_ >= octreeDate_ && oct1Date_ >= matDate_ && oct1Date_ >= illumDate_) return;
    buildIlluminated(ocopts);
}

// The octree with the illum files, mkillum on it, and the frozen octree of its output.
void Executive::buildIlluminated(const std::string& ocopts) {
    const std::string& oct = vars_.value(Var::kOctree);
    const std::string& illum = vars_.value(Var::kIllum);
    const std::string mat = vars_.defined(Var::kMaterial) ? " " + vars_.value(Var::kMaterial) : "";
    auto base = [&](const std::string& files) {
        return octreeDate_ ? " -i " + oct + " " + files : mat + " " + files;
    };
    if (oct0Date_ < sceneDate_ || oct0Date_ < illumDate_) {
        if (cmd_.touchOnly && (oct0Date_ || oct1Date_)) {
            if (oct0Date_) touch(oct0Name_);
        } else if (!runCommand(programs_.oconv + ocopts + base(illum) + " > " + oct0Name_)) {
            std::remove(oct0Name_.c_str());
            fail("error generating octree (" + oct0Name_ + " removed)");
        }
        oct0Date_ = std::max({now(), octreeDate_, illumDate_});
    }
    if (cmd_.touchOnly && oct1Date_) {
        touch(oct1Name_);
    } else {
        const std::string tmp = temporaryName(nprocs_ != 0);
        const std::string mkopts =
            parallelToolOptions(vars_, Var::kMkillum, nprocs_, programs_.mkillum);
        if (!runCommand(programs_.mkillum + mkopts + " " + oct0Name_ + " \"<\" " + illum + " > " +
                        tmp)) {
            std::remove(tmp.c_str());
            fail("error running " + programs_.mkillum);
        }
        removeFile(oct0Name_);
        const std::string frozen = octreeDate_ ? " -i " + oct + " " + tmp : mat + " " + tmp;
        if (!runCommand(programs_.oconv + ocopts + " -f" + frozen + " > " + oct1Name_)) {
            std::remove(oct1Name_.c_str());
            std::remove(tmp.c_str());
            fail("error generating octree (" + oct1Name_ + " removed)");
        }
        removeFile(tmp);
    }
    oct1Date_ = std::max(now(), oct0Date_);
}

// " -t secs [-e errfile]" from REPORT ("minutes [errfile]").
std::string reportOptions(const RifVars& vars) {
    if (!vars.defined(Var::kReport)) return "";
    double minutes = 0;
    char errfile[4096];
    const int n = std::sscanf(vars.value(Var::kReport).c_str(), "%lf %4095s", &minutes, errfile);
    if (n == 2) return formatLine(" -t %d -e %s", int(minutes * 60), errfile);
    if (n == 1) return formatLine(" -t %d", int(minutes * 60));
    throw InputError(vars.where(Var::kReport), "bad value for variable 'REPORT'");
}

// " file nphotons" of a PGMAP or PCMAP value (mkpmap gets no bandwidth).
std::string mapWithoutBandwidth(const std::string& value) {
    const std::vector<std::string> w = valueWords(value);
    return " " + w[0] + " " + w[1];
}

// RADIANCE's mkpmap(): the photon maps that are missing or older than the octree.
void Executive::makePhotonMaps() {
    const bool pgStale = !pgmapName_.empty() && pgmapDate_ < oct1Date_;
    const bool pcStale = !pcmapName_.empty() && pcmapDate_ < oct1Date_;
    if (!pgStale && !pcStale) return;
    if (cmd_.touchOnly && (pgmapName_.empty() || pgmapDate_ > 0) &&
        (pcmapName_.empty() || pcmapDate_ > 0)) {
        if (!pgmapName_.empty()) touch(pgmapName_);
        if (!pcmapName_.empty()) touch(pcmapName_);
    } else {
        const std::string opts =
            parallelToolOptions(vars_, Var::kMkpmap, nprocs_, programs_.mkpmap);
        std::string c = programs_.mkpmap + opts;
        c += " -fo+" + reportOptions(vars_);
        if (pgStale) c += " -apg" + mapWithoutBandwidth(vars_.value(Var::kPgmap));
        if (pcStale) c += " -apc" + mapWithoutBandwidth(vars_.value(Var::kPcmap));
        c += " " + oct1Name_;
        if (!runCommand(c)) {
            if (pgStale) std::remove(pgmapName_.c_str());
            if (pcStale) std::remove(pcmapName_.c_str());
            fail("error running " + programs_.mkpmap);
        }
    }
    const Date t = now();
    if (!pgmapName_.empty()) pgmapDate_ = t;
    if (!pcmapName_.empty()) pcmapDate_ = t;
    oct1Date_ = t;  // an older ambient file goes
}

void Executive::checkAmbientFile() {
    if (!vars_.defined(Var::kAmbFile)) return;
    const std::string& amb = vars_.value(Var::kAmbFile);
    const Date d = fileDate(amb);
    if (!d || oct1Date_ <= d) return;
    if (cmd_.touchOnly)
        touch(amb);
    else
        removeFile(amb);
}

// RADIANCE's xferopts: with OPTFILE the rendering options go to that file, one option
// a line, and the command reads them with @file.
std::string Executive::transferOptions(const std::string& render) {
    if (render.size() < 2 || !vars_.defined(Var::kOptFile)) return render;
    std::string text = render.substr(1);
    for (std::size_t i = 0; i + 1 < text.size(); ++i)
        if (std::isspace(static_cast<unsigned char>(text[i])) &&
            (text[i + 1] == '@' || (text[i + 1] == '-' && i + 2 < text.size() &&
                                    std::isalpha(static_cast<unsigned char>(text[i + 2])))))
            text[i] = '\n';
    text += '\n';
    const std::string& file = vars_.value(Var::kOptFile);
    std::ofstream f(file, std::ios::binary | std::ios::trunc);
    if (!(f << text) || !f.flush())
        throw InputError(SourceLoc{file, 0}, "cannot write rendering options");
    return " @" + file;
}

void Executive::printView(const std::string& view) {
    View v;
    applyViewString(v, view);
    std::lock_guard<std::mutex> lock(outMutex_);
    out_ << viewHeaderLine(v) << '\n';
}

// RADIANCE's rvu(): the first (or selected) view in rvu.
void Executive::runRvu(const std::string& render, const std::string& picture) {
    if (cmd_.touchOnly) return;
    const std::optional<std::string> vw =
        selectView(vars_, cmd_.viewSelect ? &*cmd_.viewSelect : nullptr, 0, nullptr);
    if (!vw) return;
    if (cmd_.sayView) printView(*vw);
    std::string c = programs_.rvu + " " + *vw + render + picture + " -R " + cmd_.rifFile + " ";
    if (nprocs_ > 1) c += formatLine("-n %d ", nprocs_);
    c += "-o " + cmd_.device + " ";
    if (vars_.defined(Var::kExposure)) c += "-pe " + vars_.value(Var::kExposure) + " ";
    c += oct1Name_;
    if (!runCommand(c)) fail("error running " + programs_.rvu);
}

// What every view's rendering shares.
struct Executive::ViewJob {
    std::string render;   // rendering options
    std::string picture;  // -ps -pt and the rpict variable's
    std::string pfilt;    // pfilt's options
    std::string report;   // -t -e from REPORT
    std::string resolution;
    int mult = 1;     // supersampling: rpict renders mult x the size, pfilt reduces
    int threads = 0;  // rpict -n (0: not given)
};

// One view: overture, rpict, pfilt, and the raw picture removed or renamed (RADIANCE's
// rpict() loop body). A picture newer than the octree is left alone; a raw picture newer
// than it is an interrupted rendering, recovered with rpict -ro.
void Executive::renderView(const ViewJob& job, const std::string& vw, const std::string& vs) {
    if (cmd_.sayView) printView(vw);
    const std::string& pictureRoot = vars_.value(Var::kPicture);
    const std::string picfile = pictureRoot + "_" + vs + ".hdr";
    const std::string zopt =
        vars_.defined(Var::kZfile) ? " -z " + vars_.value(Var::kZfile) + "_" + vs + ".zbf" : "";
    const Date pfdt = fileDate(picfile);
    if (pfdt >= oct1Date_) return;
    const bool raw = vars_.defined(Var::kRawFile);
    const std::string rawRoot = raw ? vars_.value(Var::kRawFile) : pictureRoot;
    const std::string rawfile = rawRoot + "_" + vs + ".unf";
    const Date rfdt = fileDate(rawfile);
    if (cmd_.touchOnly) {
        if (rfdt) {
            if (rfdt < oct1Date_) touch(rawfile);
        } else if (pfdt && pfdt < oct1Date_) {
            touch(picfile);
        }
        return;
    }
    const std::string rpict =
        programs_.rpict + (job.threads ? formatLine(" -n %d", job.threads) : "") + job.report;
    std::string c;
    if (rfdt >= oct1Date_) {
        c = rpict + job.render + job.picture + zopt + " -ro " + rawfile + " " + oct1Name_;
    } else {
        if (overture_ && !runCommand(rpict + " " + vw + job.render + " -x 64 -y 64 -ps 1 " +
                                     oct1Name_ + " > /dev/null"))
            fail("error in overture for view " + vs);
        c = rpict + " " + vw + " " + job.resolution + job.render + job.picture + zopt + " " +
            oct1Name_ + " > " + rawfile;
    }
    if (!runCommand(c)) fail("error rendering view " + vs);
    if (!raw || vars_.value(Var::kRawFile) != pictureRoot) {
        const std::string size =
            job.mult > 1 ? formatLine(" -x /%d -y /%d", job.mult, job.mult) : "";
        if (!runCommand(programs_.pfilt + job.pfilt + size + " " + rawfile + " > " + picfile)) {
            std::remove(picfile.c_str());
            fail("error filtering view " + vs + " (" + picfile + " removed)");
        }
    }
    if (raw)
        moveFile(rawfile, rawRoot + "_" + vs + ".hdr");
    else
        removeFile(rawfile);
}

// Views one after another, or with -N and several views, N at a time.
void Executive::renderViews(const ViewJob& job,
                            const std::vector<std::pair<std::string, std::string>>& views) {
    const std::size_t workers =
        std::min<std::size_t>(views.size(), nprocs_ > 1 && !cmd_.touchOnly ? nprocs_ : 1);
    if (workers <= 1) {
        for (const auto& [vw, vs] : views) renderView(job, vw, vs);
        return;
    }
    std::mutex m;
    std::size_t nextView = 0;
    std::exception_ptr error;
    std::vector<std::thread> pool;
    for (std::size_t w = 0; w < workers; ++w)
        pool.emplace_back([&] {
            while (true) {
                std::size_t k;
                {
                    std::lock_guard<std::mutex> lock(m);
                    if (error || nextView >= views.size()) return;
                    k = nextView++;
                }
                try {
                    renderView(job, views[k].first, views[k].second);
                } catch (...) {
                    std::lock_guard<std::mutex> lock(m);
                    if (!error) error = std::current_exception();
                }
            }
        });
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

// RADIANCE's rpict(): the resolution (supersampled by quality), then every view.
void Executive::runRpict(const std::string& render, const std::string& picture) {
    ViewJob job;
    job.render = render;
    job.picture = picture;
    job.pfilt = pfiltOptions(vars_, programs_);
    const char q = vars_.letter(Var::kQuality);
    job.mult = q == 'L' ? 1 : q == 'M' ? 2 : 3;
    int xres = 0, yres = 0;
    double aspect = 1;
    const int n =
        std::sscanf(vars_.value(Var::kResolution).c_str(), "%d %d %lf", &xres, &yres, &aspect);
    if (n == 3)
        job.resolution =
            formatLine("-x %d -y %d -pa %.3f", job.mult * xres, job.mult * yres, aspect);
    else if (n >= 1)
        job.resolution =
            formatLine("-x %d -y %d", job.mult * xres, job.mult * (n == 1 ? xres : yres));
    else
        throw InputError(vars_.where(Var::kResolution), "bad value for variable 'RESOLUTION'");
    job.report = reportOptions(vars_);
    std::vector<std::pair<std::string, std::string>> views;
    const std::string* select = cmd_.viewSelect ? &*cmd_.viewSelect : nullptr;
    std::string name;
    for (int k = 0;; ++k) {
        const std::optional<std::string> vw = selectView(vars_, select, k, &name);
        if (!vw) break;
        views.emplace_back(*vw, name);
    }
    // One view with -N: rpict's own threads (RADIANCE: rpiece processes).
    if (views.size() == 1 && nprocs_ > 1 && programs_.rpict == "rpict" &&
        !vars_.defined(Var::kZfile))
        job.threads = nprocs_;
    renderViews(job, views);
}

void Executive::run() {
    loadVariables();
    checkFiles();
    setDefaults();
    if (cmd_.explicate) {
        std::lock_guard<std::mutex> lock(outMutex_);
        out_ << vars_.listing();
        out_.flush();
    }
    buildOctrees();
    makePhotonMaps();
    checkAmbientFile();
    const bool forRvu = !cmd_.device.empty();
    const RenderSettings s = renderSettings(vars_, cubeSize(), forRvu, programs_);
    overture_ = s.overture;
    const std::string render = transferOptions(s.render);
    if (forRvu)
        runRvu(render, s.picture);
    else
        runRpict(render, s.picture);
}

}  // namespace

const char* radUsage() {
    return "[-w][-s][-n|-N npr][-t][-e][-V][-v view][-o dev] rfile [VAR=value ..]";
}

// RADIANCE compat (rad.c main): an option is known by its second character ("-silent"
// is -s); anything else is the usage error.
RadCommand parseRadArgs(const std::vector<std::string>& args) {
    RadCommand c;
    const std::string usage = "usage: rad " + std::string(radUsage());
    OptionTable t;
    t.defaultsStops = false;
    t.messages.unknown = [usage](const std::string&) { return usage; };
    t.messages.missing = [usage](const std::string&) { return usage; };
    auto flag = [&t](const char* name, std::function<void()> set) {
        t.add(customOption(prefix(name), name, [set](OptionReader&) { set(); }));
    };
    flag("-s", [&c] { c.silent = true; });
    flag("-n", [&c] { c.nprocs = 0; });
    flag("-t", [&c] { c.touchOnly = true; });
    flag("-e", [&c] { c.explicate = true; });
    flag("-V", [&c] { c.sayView = true; });
    flag("-w", [&c] { c.noWarnings = true; });
    t.add(customOption(prefix("-N"), "-N", [&c](OptionReader& r) {
        c.nprocs = std::max(0, std::atoi(r.word().c_str()));
    }));
    t.add(customOption(prefix("-o"), "-o", [&c](OptionReader& r) { c.device = r.word(); }));
    t.add(customOption(prefix("-v"), "-v", [&c](OptionReader& r) { c.viewSelect = r.word(); }));
    std::vector<std::string> words = args;
    const OptionParse p = t.parse(words, 0);
    if (p.next >= words.size()) throw InputError(usage);
    c.rifFile = words[p.next];
    c.assignments.assign(words.begin() + long(p.next) + 1, words.end());
    return c;
}

void runRad(const RadCommand& cmd, std::ostream& out, const Shell& shell) {
    Executive(cmd, out, shell).run();
}

void putOwnFolderFirstOnPath() {
    std::vector<char> buf(4096);
    const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
    if (n <= 0) return;
    const std::string self(buf.data(), std::size_t(n));
    const std::size_t slash = self.rfind('/');
    if (slash == std::string::npos) return;
    const char* path = std::getenv("PATH");
    const std::string value = self.substr(0, slash) + (path ? ":" + std::string(path) : "");
    ::setenv("PATH", value.c_str(), 1);
}

}  // namespace rp::rad
