// The variables of a rad input file (RIF, rad(1)): the 31 names RADIANCE 5.4's rad knows,
// their abbreviations, how repeated assignments combine, the checks on their values and
// the listing `rad -e` prints. Loading follows RADIANCE's loadvars: a backslash escapes
// the next character (a newline continues the line), '#' starts a comment, a line with a
// name and no value is ignored, and spaces inside a value are squeezed to one.
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "util/error.h"

namespace rp::rad {

// In RADIANCE's (alphabetical) order, which is also the order of `rad -e`'s listing.
enum class Var {
    kAmbFile,
    kDetail,
    kExposure,
    kEyeSep,
    kIllum,
    kIndirect,
    kMaterial,
    kMkillum,
    kMkpmap,
    kObject,
    kOconv,
    kOctree,
    kOptFile,
    kPcmap,
    kPenumbras,
    kPfilt,
    kPgmap,
    kPicture,
    kQuality,
    kRawFile,
    kRender,
    kReport,
    kResolution,
    kRpict,
    kRvu,
    kScene,
    kUp,
    kVariability,
    kViews,
    kZfile,
    kZone,
    kCount
};
constexpr std::size_t kVarCount = static_cast<std::size_t>(Var::kCount);

// How assignments combine and what values are legal.
enum class VarKind {
    kOne,      // the last assignment wins (a warning for more than one)
    kCat,      // assignments are joined with spaces (file lists, option lists)
    kQuality,  // one of LOW, MEDIUM, HIGH (any prefix, any case)
    kBool,     // TRUE or FALSE (any prefix, any case)
    kInt,
    kFloat,
    kList,  // every assignment kept apart (view)
};

struct VarInfo {
    const char* name;
    int nick;  // characters an abbreviation needs
    VarKind kind;
};
const VarInfo& info(Var v);

struct Assignment {
    std::string value;
    SourceLoc loc;  // where it was made: RIF file and line, or the command line
};

class RifVars {
public:
    // Reads a RIF file; unknown variables are an InputError at their line.
    void load(const std::string& path);
    // The same from a stream whose lines are named `path` in errors.
    void load(std::istream& in, const std::string& path);
    // One assignment "NAME= value" (or "NAME value"), as from a RIF line or rad's command
    // line. Returns false for an unknown name; an empty name or value assigns nothing.
    bool assign(const std::string& text, const SourceLoc& loc);
    // RADIANCE's checkvalues: joins kCat values (each assignment is kept with its line),
    // keeps the last of single-valued ones
    // (warning through rp::warn unless `warnings` is false), checks qualitative, boolean,
    // integer and real values (InputError at the assignment's line).
    void check(bool warnings);

    bool defined(Var v) const { return !vars_[index(v)].empty(); }
    // The value: after check(), a kCat variable's assignments joined, else the first
    // (for kList, the first view); "" if undefined.
    const std::string& value(Var v) const;
    // The n-th assignment, null past the end.
    const Assignment* nth(Var v, std::size_t n) const;
    const std::vector<Assignment>& assignments(Var v) const { return vars_[index(v)]; }
    const SourceLoc& where(Var v) const;
    // UPPER(value[0]) as RADIANCE's vlet/vscale: 'L', 'M', 'H', 'T', 'F', 'E', 'I', ...
    char letter(Var v) const;
    bool isTrue(Var v) const { return letter(v) == 'T'; }
    // Sets an undefined variable (rad's defaults).
    void setDefault(Var v, const std::string& value);

    // `rad -e`'s listing: every assignment as "NAME= value", long lines broken as
    // RADIANCE's printvars breaks them.
    std::string listing() const;

private:
    static std::size_t index(Var v) { return static_cast<std::size_t>(v); }
    std::array<std::vector<Assignment>, kVarCount> vars_;
    std::array<std::string, kVarCount> joined_;  // kCat values after check()
};

// RADIANCE's matchvar: the first variable whose name starts with `name`, at least `nick`
// characters long; false if none.
bool matchVar(const std::string& name, Var& out);

// Words of a value as RADIANCE's nextword splits them: on white space, with '"' or '\''
// quoting a word (quotes removed).
std::vector<std::string> valueWords(const std::string& value);

}  // namespace rp::rad
