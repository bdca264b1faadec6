// rad, RADIANCE's executive for oconv, mkillum, mkpmap, rpict, rvu and pfilt (rad(1)):
// reads a RIF, works out what is stale from file dates, and runs (or with -n prints)
// the commands that bring the octree, the illum sources, the photon maps, the ambient
// file and each view's picture up to date, as RADIANCE 5.4's rad.c does:
// - the octree is rebuilt when older than a scene or object file; with illum files,
//   NAME0.oct is made from it and them, mkillum turns them into light sources and the
//   frozen NAME1.oct is rendered;
// - photon maps (PGMAP, PCMAP) are made when missing or older than the rendered octree;
// - an ambient file older than the octree is removed;
// - each view without an up-to-date picture gets an overture run (if an ambient file
//   is kept and indirect light computed), rpict, then pfilt (anti-aliasing, exposure).
// Deviations from RADIANCE 5.4 (bugs there, or tools we do not have):
// - one view with -N renders through rpiece's N processes there; here rpict gets -n N
//   threads (same picture, no sync files). Several views render N at a time, as there;
// - a photon map made again (missing, or older than the octree) makes the pictures
//   again; RADIANCE forgot the map's date when it read the octree's cube;
// - `mkpmap = program options` runs that program (RADIANCE ran mkpmap with the options);
// - file dates are compared to the nanosecond, not the second.
#pragma once

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace rp::rad {

struct RadCommand {
    bool silent = false;                    // -s: do not echo commands
    bool explicate = false;                 // -e: list the variables
    bool touchOnly = false;                 // -t: bring file dates up to date, run nothing
    bool sayView = false;                   // -V: print each view
    bool noWarnings = false;                // -w
    int nprocs = 1;                         // -n: 0 (print only); -N n
    std::string device;                     // -o dev: rvu instead of rpict
    std::optional<std::string> viewSelect;  // -v view
    std::string rifFile;
    std::vector<std::string> assignments;  // VAR=value words after the RIF
};

// rad [-w][-s][-n|-N npr][-t][-e][-V][-v view][-o dev] rfile [VAR=value ..]
// Throws InputError with RADIANCE's usage line for anything else.
RadCommand parseRadArgs(const std::vector<std::string>& args);
const char* radUsage();

// Runs one command line through the shell and returns its status (0: success).
using Shell = std::function<int(const std::string& command)>;

// Runs rad; commands are echoed (unless -s) and -e/-V output written to `out`. Throws
// InputError for bad RIF input (file and line), missing files, and a failed command.
void runRad(const RadCommand& cmd, std::ostream& out, const Shell& shell);

// The commands rad runs find radphoton's tools first: the folder of the running program
// goes ahead of PATH (a RADIANCE installation later on PATH is not mixed in).
void putOwnFolderFirstOnPath();

}  // namespace rp::rad
