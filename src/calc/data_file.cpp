// Reading and interpolating RADIANCE data files (see data_file.h).
#include "calc/data_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "util/data_words.h"
#include "util/error.h"

namespace rp::calc {
namespace {

// The numbers of a data file, read as RADIANCE's fgetval reads them (comments
// included), with the line of each for error messages.
class NumberReader {
public:
    NumberReader(std::string_view text, std::string name)
        : words_(splitDataWords(text)), name_(std::move(name)) {}

    double number(const char* what) {
        if (next_ >= words_.size())
            throw InputError(SourceLoc{name_, words_.empty() ? 1 : words_.back().line},
                             "unexpected end of file: expected " + std::string(what));
        const DataWord& w = words_[next_++];
        char* end = nullptr;
        errno = 0;
        double v = std::strtod(w.text.c_str(), &end);
        if (end == w.text.c_str() || *end != '\0' || !std::isfinite(v))
            fail("expected " + std::string(what) + ", found '" + w.text + "'");
        return v;
    }
    int count(const char* what) {
        double v = number(what);
        if (v != std::floor(v) || v < 1 || v > 1e9)
            fail(std::string(what) + " must be a positive integer");
        return static_cast<int>(v);
    }
    bool atEnd() const { return next_ >= words_.size(); }
    // Reports at the word last read.
    [[noreturn]] void fail(const std::string& msg) const { failAt(next_ > 0 ? next_ - 1 : 0, msg); }
    // Reports at the first word not read.
    [[noreturn]] void failAtNext(const std::string& msg) const { failAt(next_, msg); }

private:
    [[noreturn]] void failAt(std::size_t word, const std::string& msg) const {
        int line = words_.empty() ? 1 : words_[std::min(word, words_.size() - 1)].line;
        throw InputError(SourceLoc{name_, line}, msg);
    }

    std::vector<DataWord> words_;
    std::string name_;
    std::size_t next_ = 0;
};

// Position along one axis: the lower sample index i and the weights of samples i and
// i+1, including RADIANCE's extrapolation beyond the ends.
struct AxisWeights {
    int i = 0;
    double w0 = 1, w1 = 0;
};

AxisWeights weights(const DataFile::Axis& a, double coord) {
    AxisWeights r;
    if (a.count == 1) return r;  // a single sample: constant along this axis
    double x;                    // fractional sample index
    if (a.points.empty()) {
        x = (coord - a.begin) / (a.end - a.begin) * (a.count - 1);
        // Clamped before the conversion: a far (or NaN) coordinate has no int index.
        const double f = std::floor(x);
        r.i = !(f >= 0) ? 0 : f > a.count - 2 ? a.count - 2 : static_cast<int>(f);
    } else {
        const auto& p = a.points;
        bool up = p.back() > p.front();
        // Largest i in [0, count-2] with coord past p[i] in the axis' direction.
        int lo = 0, hi = a.count - 2;
        while (lo < hi) {
            int mid = (lo + hi + 1) / 2;
            if (up ? coord >= p[mid] : coord <= p[mid])
                lo = mid;
            else
                hi = mid - 1;
        }
        r.i = lo;
        x = lo + (coord - p[lo]) / (p[lo + 1] - p[lo]);
    }
    r.i = std::clamp(r.i, 0, a.count - 2);
    const double i = r.i;
    if (x > i + 2) {  // more than one division past the end: taper to zero
        r.w0 = -1 / (x - (i - 1));
        r.w1 = 2 / (x - (i - 1));
    } else if (x < i - 1) {
        r.w0 = 2 / (i - x);
        r.w1 = -1 / (i - x);
    } else {
        r.w0 = (i + 1) - x;
        r.w1 = x - i;
    }
    return r;
}

}  // namespace

DataFile DataFile::load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, "cannot open data file");
    std::stringstream ss;
    ss << in.rdbuf();
    return parse(ss.str(), path);
}

DataFile DataFile::parse(std::string_view text, const std::string& name) {
    NumberReader r(text, name);
    DataFile d;
    int n = r.count("number of dimensions");
    if (n > kMaxDimensions)
        r.fail("too many dimensions (" + std::to_string(n) + ", at most " +
               std::to_string(kMaxDimensions) + ")");
    std::size_t total = 1;
    for (int k = 0; k < n; ++k) {
        Axis a;
        a.begin = r.number("axis begin");
        a.end = r.number("axis end");
        a.count = r.count("axis point count");
        if (a.begin == a.end) {  // listed coordinates follow
            for (int j = 0; j < a.count; ++j) a.points.push_back(r.number("axis coordinate"));
            for (int j = 1; j + 1 < a.count; ++j)
                if ((a.points[j - 1] < a.points[j]) != (a.points[j] < a.points[j + 1]))
                    r.fail("axis " + std::to_string(k + 1) + " coordinates are not monotonic");
            for (int j = 1; j < a.count; ++j)
                if (a.points[j] == a.points[j - 1])
                    r.fail("axis " + std::to_string(k + 1) + " has repeated coordinates");
            a.begin = a.points.front();
            a.end = a.points.back();
        } else if (a.count == 1) {
            r.fail("axis " + std::to_string(k + 1) + " has distinct ends but a single point");
        }
        total *= static_cast<std::size_t>(a.count);
        if (total > (std::size_t{1} << 31)) r.fail("data array too large");
        d.axes_.push_back(std::move(a));
    }
    // No more than the text can hold (a value takes at least two characters): a short
    // file declaring a huge array fails at its end instead of reserving gigabytes first
    // (fuzz_data_file's out-of-memory finding).
    d.values_.reserve(std::min(total, text.size() / 2 + 1));
    for (std::size_t j = 0; j < total; ++j) d.values_.push_back(r.number("data value"));
    if (!r.atEnd())
        r.failAtNext("more data than the axes declare (" + std::to_string(total) + " values)");
    d.strides_.assign(n, 1);
    for (int k = n - 2; k >= 0; --k) d.strides_[k] = d.strides_[k + 1] * d.axes_[k + 1].count;
    return d;
}

double DataFile::value(std::span<const double> point) const {
    RP_CHECK(static_cast<int>(point.size()) >= dimensions());
    const int n = dimensions();
    AxisWeights w[kMaxDimensions];
    for (int k = 0; k < n; ++k) w[k] = weights(axes_[k], point[k]);
    // Sum over the 2^n corners of the cell; the per-axis rules are linear in the two
    // sample values, so this equals RADIANCE's axis-by-axis recursion.
    double sum = 0;
    for (unsigned corner = 0; corner < (1u << n); ++corner) {
        double weight = 1;
        std::size_t idx = 0;
        for (int k = 0; k < n; ++k) {
            bool hi = (corner >> k) & 1;
            if (axes_[k].count == 1) {
                if (hi) {
                    weight = 0;
                    break;
                }
                continue;
            }
            weight *= hi ? w[k].w1 : w[k].w0;
            idx += (w[k].i + (hi ? 1 : 0)) * strides_[k];
        }
        if (weight != 0) sum += weight * values_[idx];
    }
    return sum;
}

}  // namespace rp::calc
