// rcollate's two ways of working (rcollate.h): reordering records held in memory
// (RADIANCE rcollate.c do_reorder, for transposes, blocks and checks) and reshaping an
// ASCII stream by moving its line breaks (do_resize).
#include <cctype>

#include "matrix/rcollate.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::matrix {

namespace {

using Index = long long;

bool isWordSpace(char c) { return c == '\0' || std::isspace(static_cast<unsigned char>(c)); }

// Where each ASCII record of `words` words starts (index_records); the data's end follows.
struct RecordIndex {
    int words = 0;
    std::vector<size_t> start;  // one per record, then the end of the data
};

RecordIndex indexRecords(const DataReader& r, int words) {
    const char* b = r.cursor();
    const size_t end = r.remaining();
    RecordIndex ix{words, {}};
    size_t cp = 0;
    for (;;) {
        while (cp < end && isWordSpace(b[cp])) ++cp;
        if (cp >= end) break;
        ix.start.push_back(cp);
        int n = words;
        while (++cp < end) {
            if (!isWordSpace(b[cp])) continue;
            if (--n <= 0) break;
            do {  // to the record's next word, which must be on the same line
                if (b[cp] == '\n') {
                    int line = r.line();
                    for (size_t i = 0; i < cp; ++i) line += b[i] == '\n';
                    throw InputError(SourceLoc{r.name(), line},
                                     "unexpected end of line in record " +
                                         std::to_string(ix.start.size()) + " (" +
                                         std::to_string(words) + " words per record)");
                }
                if (++cp >= end) break;
            } while (isWordSpace(b[cp]));
        }
    }
    ix.start.push_back(end);
    return ix;
}

// count_columns: the records that start on the first line.
int countColumns(const DataReader& r, const RecordIndex& ix) {
    const char* b = r.cursor();
    size_t cp = ix.start[0];
    const size_t end = ix.start.back();
    while (b[cp] != '\n')
        if (++cp >= end) return 0;
    int i = 0;
    while (i + 1 < static_cast<int>(ix.start.size()) && ix.start[static_cast<size_t>(i)] < cp) ++i;
    return i;
}

// print_record: the record's words with single spaces between them.
void appendRecord(const DataReader& r, const RecordIndex& ix, Index n, std::string& s) {
    const char* b = r.cursor();
    const size_t limit = ix.start[static_cast<size_t>(n) + 1];
    const size_t dataEnd = ix.start.back();
    auto at = [&](size_t i) { return i < dataEnd ? b[i] : '\0'; };
    int words = ix.words;
    size_t p = ix.start[static_cast<size_t>(n)];
    do {
        s += b[p++];
        if (isWordSpace(at(p))) {
            if (--words <= 0) break;
            s += ' ';
            do
                if (++p >= limit) break;
            while (isWordSpace(at(p)));
        }
    } while (p < limit);
}

// get_block_pos: the input record for output (r, c) through the block levels.
Index blockPosition(int r, int c, const std::vector<std::pair<int, int>>& lv) {
    Index n = 0;
    size_t i = 0;
    for (; i + 1 < lv.size(); ++i) {
        const int sr = r / lv[i + 1].first, sc = c / lv[i + 1].second;
        r -= sr * lv[i + 1].first;
        c -= sc * lv[i + 1].second;
        n += static_cast<Index>(sr) * lv[i + 1].first * lv[i].second +
             static_cast<Index>(sc) * lv[i + 1].first * lv[i + 1].second;
    }
    return n + static_cast<Index>(r) * lv[i].second + c;
}

Index inputPosition(const RcollateOptions& o, int r, int c) {
    if (o.blocks.size() > 1) {
        Index n = blockPosition(r, c, o.blocks);
        if (o.transpose) {
            const Index tr = n / o.inRows, tc = n - tr * o.inRows;
            n = tc * o.inCols + tr;
        }
        return n;
    }
    if (o.transpose) return static_cast<Index>(c) * o.inCols + r;
    return static_cast<Index>(r) * o.outCols + c;
}

InputError badSize(const DataReader& r, const std::string& what) {
    return InputError(SourceLoc{r.name(), 0}, what);
}

// The input and output sizes do_reorder settles on; throws for ones that do not fit.
Index settleSizes(RcollateOptions& o, const DataReader& r, const RecordIndex* ix) {
    Index records;
    if (ix) {
        if (o.inCols <= 0) o.inCols = countColumns(r, *ix);
        records = static_cast<Index>(ix->start.size()) - 1;
    } else {
        const Index recordBytes = static_cast<Index>(o.components) * o.componentSize;
        const Index available = static_cast<Index>(r.remaining()) / recordBytes;
        if (o.inRows > 0 && o.inCols > 0) {
            records = static_cast<Index>(o.inRows) * o.inCols;
            if (records > available)
                throw badSize(r, "input too small for specified size and type (" +
                                     std::to_string(available) + " records, need " +
                                     std::to_string(records) + ")");
        } else {
            records = available;
        }
    }
    if (o.inRows <= 0 && o.inCols > 0)
        o.inRows = static_cast<int>(records / o.inCols);
    else if (o.inCols <= 0 && o.inRows > 0)
        o.inCols = static_cast<int>(records / o.inRows);
    const std::string inSize = std::to_string(o.inRows) + "x" + std::to_string(o.inCols);
    if (records != static_cast<Index>(o.inRows) * o.inCols)
        throw badSize(
            r, "bad dimension(s): " + std::to_string(records) + " records do not make " + inSize);
    if (o.transpose) {
        if (o.outCols <= 0) o.outCols = o.inRows;
        if (o.outRows <= 0) o.outRows = o.inCols;
        if (o.blocks.size() <= 1 && (o.outRows != o.inCols || o.outCols != o.inRows))
            throw badSize(r, "bad dimension(s): cannot transpose " + inSize + " to " +
                                 std::to_string(o.outRows) + "x" + std::to_string(o.outCols));
    } else {
        if (o.outCols <= 0) o.outCols = o.inCols;
        if (o.outRows <= 0) o.outRows = o.inRows;
    }
    if (static_cast<Index>(o.inRows) * o.inCols != static_cast<Index>(o.outRows) * o.outCols)
        throw badSize(r, "number of input and output records do not match (" + inSize + " and " +
                             std::to_string(o.outRows) + "x" + std::to_string(o.outCols) + ")");
    return records;
}

}  // namespace

void reorderRecords(RcollateOptions& o, DataReader& r, std::ostream& out) {
    if (o.inRows <= 0) o.inRows = o.transpose ? o.outCols : o.outRows;
    if (o.inCols <= 0) o.inCols = o.transpose ? o.outRows : o.outCols;
    RecordIndex ix;
    const bool ascii = o.componentSize == 0;
    if (ascii) ix = indexRecords(r, o.components);
    const Index records = settleSizes(o, r, ascii ? &ix : nullptr);
    if (o.outHeader) out << "NROWS=" << o.outRows << "\nNCOLS=" << o.outCols << "\n\n";
    const size_t recordBytes = static_cast<size_t>(o.components) * o.componentSize;
    std::string s;
    for (int i = 0; i < o.outRows; ++i) {
        for (int j = 0; j < o.outCols; ++j) {
            const Index n = inputPosition(o, i, j);
            if (n >= records) throw badSize(r, "index past end of data");
            if (ascii) {
                appendRecord(r, ix, n, s);
                s += j >= o.outCols - 1 ? '\n' : '\t';
            } else {
                s.append(r.cursor() + static_cast<size_t>(n) * recordBytes, recordBytes);
            }
        }
        out.write(s.data(), static_cast<std::streamsize>(s.size()));
        s.clear();
    }
}

}  // namespace rp::matrix
