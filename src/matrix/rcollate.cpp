// rcollate's work (see rcollate.h), after RADIANCE rcollate.c.
#include "matrix/rcollate.h"

#include <cctype>
#include <cstdlib>
#include <cstring>

#include "util/error.h"
#include "util/header.h"
#include "util/warnings.h"

namespace rp::matrix {

namespace {

using Index = long long;  // record counts and positions (RADIANCE ssize_t)

bool startsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

// The header's sizes and format checked against the options (rcollate.c headline); the
// other lines are copied to `copied` when there is an output header.
void readInputHeader(DataReader& r, RcollateOptions& o, std::string& copied) {
    std::vector<std::string> lines;
    if (!r.readHeader(lines))
        throw InputError(SourceLoc{r.name(), 0},
                         "bad header (no information header ended by an empty line; -hi "
                         "reads data without one)");
    auto count = [&](const std::string& line, int& field, const char* what) {
        const int n = std::atoi(line.c_str() + 6);
        if (field > 0 && n != field)
            throw InputError(SourceLoc{r.name(), 0}, std::string("incorrect input ") + what +
                                                         " (header " + std::to_string(n) +
                                                         ", option " + std::to_string(field) + ")");
        field = n;
    };
    for (const std::string& line : lines) {
        char fmt[64] = "";
        if (startsWith(line, "FORMAT=") && std::sscanf(line.c_str() + 7, " %63s", fmt) == 1) {
            if (o.format.empty())
                o.format = fmt;
            else if (o.format != fmt)
                throw InputError(SourceLoc{r.name(), 0},
                                 "input format '" + std::string(fmt) + "' != '" + o.format + "'");
        } else if (startsWith(line, "NROWS=")) {
            count(line, o.inRows, "row count");
        } else if (startsWith(line, "NCOLS=")) {
            count(line, o.inCols, "column count");
        } else if (startsWith(line, "NCOMP=")) {
            count(line, o.components, "number of components");
        } else if (o.outHeader) {
            copied += line;
        }
    }
}

// rcollate.c check_sizes: the word size for the format, and sizes the options imply.
void checkSizes(RcollateOptions& o) {
    if (o.format.empty()) {
        o.format = "ascii";
    } else if (!o.componentSize) {
        if (o.format == "float")
            o.componentSize = 4;
        else if (o.format == "double")
            o.componentSize = 8;
        else if (o.format == "byte")
            o.componentSize = 1;
        else if (o.format != "ascii")
            throw InputError("unsupported format: " + o.format);
    }
    if (o.transpose && o.outRows <= 0 && o.outCols <= 0) {
        if (o.inRows > 0) o.outCols = o.inRows;
        if (o.inCols > 0) o.outRows = o.inCols;
    } else if (o.outRows <= 0 && o.outCols > 0 &&
               !((static_cast<Index>(o.inRows) * o.inCols) % o.outCols)) {
        o.outRows = static_cast<int>(static_cast<Index>(o.inRows) * o.inCols / o.outCols);
    }
    if (o.components <= 0) o.components = 3;
}

}  // namespace

// The two ways of doing the work (rcollate_reorder.cpp).
void reorderRecords(RcollateOptions& o, DataReader& r, std::ostream& out);
void resizeRecords(const RcollateOptions& o, DataReader& r, std::ostream& out);

void runRcollate(RcollateOptions o, const InputData& in, std::ostream& out) {
    DataReader r(in);
    if (!o.transpose && !o.check && o.blocks.size() <= 1 && o.inHeader == o.outHeader &&
        o.outCols == o.inCols && o.outRows == o.inRows) {
        if (o.warnings) warn("no-op -- copying input verbatim");
        out.write(in.bytes.data(), static_cast<std::streamsize>(in.bytes.size()));
        return;
    }
    std::string head;
    if (o.inHeader) readInputHeader(r, o, head);
    checkSizes(o);
    if (o.outHeader) {
        if (!o.inHeader) head = std::string(kHeaderMagic) + "\n";
        head += o.commandLine + "\nNCOMP=" + std::to_string(o.components) + "\nFORMAT=" + o.format +
                "\n";
    }
    out << head;
    if (o.transpose || o.check || o.blocks.size() > 1 || (o.outHeader && o.outRows <= 0)) {
        if (r.remaining() == 0)
            throw InputError(SourceLoc{in.name, 0}, "no data to load into memory");
        reorderRecords(o, r, out);
    } else {
        resizeRecords(o, r, out);
    }
}

}  // namespace rp::matrix
