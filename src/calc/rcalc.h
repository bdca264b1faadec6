// rcalc, RADIANCE's record calculator (rcalc(1)): reads records (tab-separated columns,
// a -i format, or binary floats/doubles), evaluates the .cal program's output channels
// `$N = expr;` (or a -o format's fields) for each, and writes one record per input
// record for which `cond`, if defined, is positive. Expressions are compiled and run by
// this module's Builder/Program/Evaluator; the formats are in record_format.h.
#pragma once

#include <istream>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "calc/program.h"
#include "calc/record_format.h"

namespace rp::calc {

struct RcalcOptions {
    bool blanksEqual = true;  // -b toggles: only exact matches
    bool ignoreEol = false;   // -l toggles: newlines count as blanks in -i formats
    bool passive = false;     // -p toggles: pass unmatched input through
    char separator = '\t';    // -tS
    bool noInput = false;     // -n: one record from no input
    bool noWarnings = false;  // -w toggles
    bool flush = false;       // -u toggles: flush after each record
    char inputType = 'a';     // -ia, -id/-iD (doubles), -if/-iF (floats; D, F byte-swapped)
    int binaryColumns = 0;    // values per binary input record (-id3)
    char outputType = 'a';    // -oa, -od, -oD, -of, -oF
    long inputLimit = 0;      // -in N: stop after N input records (per file, as RADIANCE)
    long outputLimit = 0;     // -on N: stop after N output records (per file)
    // -i / -o: the format text (recordFormatText) and -l as it was when the option came.
    std::string inputFormat, outputFormat;
    bool inputFormatIgnoreEol = false, outputFormatIgnoreEol = false;
    bool hasInputFormat = false, hasOutputFormat = false;
    // -e text and -f files, in command-line order (true: a file to find on the path).
    std::vector<std::pair<bool, std::string>> sources;
    std::vector<std::string> presets;  // -s svar=sval
};

class Rcalc {
public:
    // Compiles the program (-f files found along `searchPath`). InputError for a missing
    // file, a syntax error, a bad format.
    Rcalc(const RcalcOptions& options, const std::vector<std::string>& searchPath);
    ~Rcalc();

    // Processes one input (`name` for messages); output records go to `out`.
    void run(std::istream& in, const std::string& name, std::ostream& out);
    // -n: one output record without input.
    void runNoInput(std::ostream& out);

    // Divisions by zero and bad library calls so far (each gave 0).
    long mathErrors() const;

private:
    class Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rp::calc
