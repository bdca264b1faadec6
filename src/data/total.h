// total, RADIANCE's column reducer (total(1)): sums, products, maxima or minima of the
// columns of ASCII or binary records, for whole files, every N records or at each blank
// line, optionally as running totals (-r) or means (-m). The tool's options are parsed
// in tools/total.cpp; this is the computation, following RADIANCE total.c.
#pragma once

#include <istream>
#include <ostream>
#include <string>

namespace rp::data {

struct TotalOptions {
    enum class Func { Add, Multiply, Max, Min };
    Func func = Func::Add;  // -s (Add), -p, -u, -l
    double power = 0;       // -sE: sum of |x|^E (0: plain sum)
    bool mean = false;      // -m toggles
    int count = 0;          // -N: a result every N records (0: at blank lines and ends)
    bool subtotal = false;  // -r toggles: running results, not reset after each
    char separator = '\t';  // -tC, input and output
    int binaryColumns = 0;  // -idN: N doubles per record; -ifN: -N (floats); 0: ASCII
    int binaryOutput = 0;   // -od: 1, -of: -1, -oa: 0
    long inputLimit = 0;    // -in M: at most M records per result batch of a file
    long outputLimit = 0;   // -on M: at most M results in all
};

// Columns a record may have (RADIANCE MAXCOL).
constexpr int kTotalMaxColumns = 8192;

class Total {
public:
    explicit Total(const TotalOptions& o) : o_(o) {}
    // Reduces one input file, writing its results to `out`. Returns false once the
    // -on limit is reached (no more files need reading).
    bool run(std::istream& in, std::ostream& out);
    bool done() const { return o_.outputLimit > 0 && recordsOut_ >= o_.outputLimit; }

private:
    int readRecord(std::istream& in, double* field);
    void writeRecord(const double* field, int n, std::ostream& out);

    TotalOptions o_;
    long recordsOut_ = 0;
    std::string line_;  // the ASCII record being read
};

}  // namespace rp::data
