// rcollate's reshaping of an ASCII stream (RADIANCE rcollate.c do_resize and fget_word):
// records keep their words, only the line breaks between them move.
#include <cctype>

#include "matrix/rcollate.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::matrix {

namespace {

// The stream side of DataReader that fget_word needs.
class WordStream {
public:
    explicit WordStream(DataReader& r) : r_(r) {}
    int get() {
        if (!r_.remaining()) return EOF;
        const int c = static_cast<unsigned char>(*r_.cursor());
        r_.seek(r_.position() + 1);
        return c;
    }
    void unget() { r_.seek(r_.position() - 1); }
    // The next word (at most 255 characters), leaving the stream at the end of line or
    // the start of the next word; false at the end of the data.
    bool word(std::string& w) {
        int c;
        while ((c = get()) == 0 || (c != EOF && std::isspace(c))) {
        }
        if (c == EOF) return false;
        lastWord_ = r_.position() - 1;
        w.clear();
        do w += static_cast<char>(c);
        while ((c = get()) != EOF && !std::isspace(c) && w.size() < 255);
        while (c != EOF && std::isspace(c) && c != '\n') c = get();
        if (c != EOF) unget();
        return true;
    }

    int lastWordLine() const { return r_.lineAt(lastWord_); }

private:
    DataReader& r_;
    size_t lastWord_ = 0;
};

}  // namespace

void resizeRecords(const RcollateOptions& o, DataReader& r, std::ostream& out) {
    long long recordsToGo = static_cast<long long>(o.inRows) * o.inCols;
    if (o.outHeader) {
        if (o.outRows > 0) out << "NROWS=" << o.outRows << '\n';
        if (o.outCols > 0) out << "NCOLS=" << o.outCols << '\n';
        out << '\n';
    }
    if (o.componentSize || (!o.check && o.outCols == o.inCols && o.outRows == o.inRows)) {
        out.write(r.cursor(), static_cast<std::streamsize>(r.remaining()));  // no-op: copy
        return;
    }
    if (o.outCols <= 0) throw InputError("missing -oc specification");
    const long long outRecords = static_cast<long long>(o.outRows) * o.outCols;
    if (recordsToGo <= 0 && o.outRows > 0)
        recordsToGo = outRecords;
    else if (outRecords != recordsToGo)
        throw InputError("number of input and output records disagree (" +
                         std::to_string(o.inRows) + "x" + std::to_string(o.inCols) + " != " +
                         std::to_string(o.outRows) + "x" + std::to_string(o.outCols) + ")");
    WordStream in(r);
    std::string word, s;
    int columnsToGo = o.outCols;
    long long record = 0;
    do {
        ++record;
        int n;
        bool endOfData = false;
        for (n = o.components; n--;) {
            if (!in.word(word)) {
                // RADIANCE compat: an unknown record count ends cleanly between records.
                endOfData = recordsToGo <= 0 && n == o.components - 1;
                break;
            }
            s += word;
            if (n) {  // mid-record: the next word must be on the same line
                const int c = in.get();
                if (c == '\n' || c == EOF) break;
                in.unget();
                s += ' ';
            }
        }
        if (endOfData) break;
        if (n >= 0)
            throw InputError(
                SourceLoc{r.name(), in.lastWordLine()},
                "incomplete record " + std::to_string(record) + " or unexpected end of data");
        if (--columnsToGo <= 0) {
            s += '\n';
            columnsToGo = o.outCols;
        } else {
            s += '\t';
        }
        if (s.size() > 65536) {
            out.write(s.data(), static_cast<std::streamsize>(s.size()));
            s.clear();
        }
    } while (--recordsToGo);
    out.write(s.data(), static_cast<std::streamsize>(s.size()));
    if (o.warnings && columnsToGo != o.outCols) warn("incomplete final row");
    if (o.warnings && in.word(word)) warn("characters beyond expected end of data");
}

}  // namespace rp::matrix
