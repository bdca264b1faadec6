// rlam, RADIANCE's record laminator (rlam(1)): one record from each input in turn (a
// line, N lines, or N binary values), joined by each input's separator, record after
// record until an input runs out. Inputs are files, "-" (standard input) or "!command"s.
// The tool's options are parsed in tools/rlam.cpp; this is the reading and joining.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace rp::data {

// The largest line and binary record (RADIANCE's MAXLINE, the fgets buffer).
constexpr int kRlamMaxLine = 65536;

// One input with the settings in force where it was named.
struct RlamInput {
    std::string name;       // a file, "-" or "!command"
    std::string separator;  // printed before its record (never before the first input's)
    int recordBytes = 0;    // > 0: binary records of this many bytes; 0: one line;
                            // < 0: -recordBytes lines joined by the separator
};

// The inputs' settings as the options before them set them (-t, -i...), RADIANCE's
// rules: a binary -i format resets the separator to none.
struct RlamState {
    std::string separator = "\t";
    int recordBytes = 0;
    bool binaryOutput = false;  // some input is binary
    // -tS: S, or a newline for a bare -t.
    void setSeparator(const std::string& s) { separator = s.empty() ? "\n" : s; }
    // -ia -if -id -ii -iw -ib with an optional count ("-if3"), the word's letters after
    // "-i". Throws InputError for another letter ("bad option") or a record over
    // kRlamMaxLine bytes ("input size too big").
    void setFormat(const std::string& format);
};

struct RlamStream {
    std::FILE* file;
    const RlamInput* input;
};

// Laminates `streams` onto `out` (RADIANCE lam.c's loop): at most `limit` records when
// limit > 0. A newline ends each output record when some input is not binary; -u
// (`unbuffered`) flushes after each. The record in which an input runs out is written
// as far as it got, without its newline. Returns false when the output failed or `limit`
// was positive and not reached ("premature EOD", a warning in RADIANCE).
struct RlamResult {
    bool writeError = false;
    bool premature = false;
};
RlamResult laminate(const std::vector<RlamStream>& streams, long limit, bool unbuffered,
                    std::FILE* out);

// Opens every input (fopen, popen for "!command", stdin for "-"), laminates them and
// closes them. Throws InputError: "NAME: cannot open file", "NAME: cannot start command",
// "no input streams", "write error on standard output".
RlamResult rlam(const std::vector<RlamInput>& inputs, long limit, bool unbuffered, std::FILE* out);

}  // namespace rp::data
