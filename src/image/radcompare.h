// radcompare: RADIANCE 5.4's check that two RADIANCE files hold the same thing within
// tolerances. Headers are compared as variable settings (NAME=value, later ones replacing
// earlier ones, EXPOSURE multiplied, SOFTWARE CAPDATE GMT FRAME and command lines ignored),
// then the data by the FORMAT the headers name: pictures pixel by pixel (mean and largest
// primary), "ascii" and header-less text word by word with numbers compared as reals,
// "float"/"double" value by value (BYTE_ORDER honoured), anything else byte by byte.
// Depth and normal maps (16-bit_encoded_depth, 32-bit_encoded_normal) are compared byte by
// byte here, where RADIANCE decodes them first.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "util/options.h"

namespace rp {

enum class CompareReport { kQuiet, kErrors, kWarnings, kVerbose };

struct RadcompareOptions {
    CompareReport report = CompareReport::kWarnings;
    bool ignoreHeader = false;  // -h (toggles)
    char comment = '\0';        // -c#: text lines starting with # are empty
    double relMin = 1e-5;       // -rel: relative differences above this magnitude (<= 0: absolute)
    double rmsLimit = 0.01;     // -rms
    double maxLimit = 0.25;     // -max (negative: no limit)
    bool firstFromStdin = false;  // "-" as the first input
    std::string reference, test;  // file names; "-" as test reads standard input too
};

OptionTable radcompareTable(RadcompareOptions& opt);
// Throws InputError with RADIANCE's usage line for anything but options and two inputs.
RadcompareOptions parseRadcompareArgs(std::vector<std::string> args);

// Compares two files' bytes, named name1 and name2 in messages, writing RADIANCE's reports
// (as `program`) to `out`. Returns 0 when they match within tolerance, 1 when they differ;
// throws InputError (exit status 2) when an input cannot be read as its kind.
int compareRadianceData(const RadcompareOptions& opt, const std::string& name1,
                        const std::string& data1, const std::string& name2,
                        const std::string& data2, std::ostream& out,
                        const std::string& program = "radcompare");

// Opens the inputs (standard input for "-") and compares them.
int runRadcompare(const RadcompareOptions& opt, std::istream& stdinStream, std::ostream& out);

}  // namespace rp
