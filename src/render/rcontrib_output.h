// rcontrib's outputs (RADIANCE rc2.c): standard output or one stream per -o name, where
// "%s" takes the modifier name and "%d" (or %i %o %x %X) the bin number, a leading '!'
// pipes to a command; RADIANCE's headers (octree header lines, command line, SOFTWARE,
// CAPDATE/GMT, NCOMP=3, MODIFIER=, BIN=, NROWS=, NCOLS=, byte order, FORMAT=), the
// resolution string of pictures, records in -fa/-ff/-fd/-fc, and -r recovery.
//
// Files are written in place as records come, as RADIANCE's: -r continues a run that
// was stopped from what its files hold, and pipes cannot be written any other way.
#pragma once

#include <cstdint>
#include <istream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "render/rcontrib_options.h"
#include "util/color.h"
#include "util/spectrum.h"

namespace rp::render {

class ContribOutput {
public:
    // Resolves every modifier's bins to streams (rcontrib.c addmodifier: a picture spec
    // shared by several modifiers offsets their bin numbers). `sceneHeader`: the lines of
    // the scene file's header (FORMAT excluded), copied into each header; `stdoutStream`
    // receives standard output. Throws InputError "bad output format 'spec'", and
    // "cannot open 'name' for writing: File exists" for an existing file without -fo or
    // -r. Streams open (and write their headers) with the first record, except with -r.
    ContribOutput(const RcontribOptions& options, std::vector<std::string> sceneHeader,
                  std::ostream& stdoutStream);
    ~ContribOutput();
    ContribOutput(const ContribOutput&) = delete;
    ContribOutput& operator=(const ContribOutput&) = delete;

    // -r (rc2.c recover_output): the number of complete records the existing outputs all
    // hold (the input rays to skip are that times -c); the files are cut back to it and
    // appended to. 0 when there is nothing to recover. Throws InputError for an output
    // whose header does not match this run (format, size) or for a pipe.
    uint64_t recover();

    // -r with -c 0 (rc2.c reload_output): the totals the existing outputs hold, in
    // modifier-then-bin order, to which this run adds; zero where an output is missing
    // (with a warning). The outputs are then written anew. Throws InputError for standard
    // output, a pipe, a header of another format or values missing.
    std::vector<Color> reload();

    // Writes one record: `values` in modifier-then-bin order (ContribTargets), each
    // multiplied by `scale` (1 / -c when averaging). `flush` forces the streams out.
    // Rendering a spectrum (-cs above 3, in passes of three bands: spectrum.h Pass),
    // `values` holds every pass's bins one pass after another, and each bin is written
    // as its samples (NCOMP=n, as RADIANCE 6's rcontrib).
    void writeRecord(const std::vector<Color>& values, double scale, bool flush);

    // Flushes and closes every stream (pipes: waits for the command). Throws InputError
    // for a write error or a command that failed.
    void close();

    struct Stream;

private:
    // The FORMAT= of the output (formatName, or Radiance_spectra for -fc with -cs above 3).
    const char* format() const;
    std::string resolution() const;  // the pictures' resolution line
    Stream& open(size_t stream);
    // One bin's samples in the output format into v[0..n).
    bool readValue(std::istream& in, double* v) const;
    const RcontribOptions& o_;
    std::vector<std::string> sceneHeader_;
    std::ostream& stdout_;
    std::vector<std::unique_ptr<Stream>> streams_;
    std::vector<std::vector<size_t>> streamOf_;  // [modifier][bin] -> streams_ index
    std::vector<int> binNumber_;                 // first bin number per modifier (bin0)
    spectral::Sampling sampling_;                // -cs -cw
    std::vector<spectral::Pass> passes_;         // of sampling_: how a record's values lie
};

// "name", or the spec with the modifier's name and bin number put in; false for a spec
// RADIANCE rejects (two %s, two bin formats, another conversion). `hasModifier` and
// `hasBin` say which it holds.
bool contribOutputName(const std::string& spec, const std::string& modifier, int bin,
                       std::string& name, bool& hasModifier, bool& hasBin);

}  // namespace rp::render
