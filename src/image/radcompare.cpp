// radcompare: see radcompare.h. The verdicts and messages follow RADIANCE 5.4's radcompare.
#include "image/radcompare.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>

#include "image/picture.h"
#include "image/radcompare_impl.h"
#include "image/rgbe.h"
#include "util/error.h"

namespace rp {
namespace radcompare_detail {

void Comparer::setVariable(Input& in, const std::string& line) {
    ++in.lines;
    if (line.empty() || !std::isalpha(static_cast<unsigned char>(line[0]))) return;
    if (line.rfind("BigEndian", 0) == 0) {  // RADIANCE's isbigendian: "BigEndian= 1"
        size_t k = 9;
        while (k < line.size() && isSpace(line[k])) ++k;
        if (k < line.size() && line[k] == '=') {
            ++k;
            while (k < line.size() && isSpace(line[k])) ++k;
            in.swapped = k < line.size() && line[k] == '1';  // this machine is little-endian
            return;
        }
    }
    size_t i = 0;
    while (i < line.size() && !isSpace(line[i]) && line[i] != '=') ++i;
    const std::string key = line.substr(0, i);
    while (i < line.size() && isSpace(line[i])) ++i;
    if (i >= line.size() || line[i] != '=') return;
    ++i;
    while (i < line.size() && isSpace(line[i])) ++i;
    size_t end = line.size();
    while (end > i && isSpace(line[end - 1])) --end;
    if (end == i) return;
    for (const char* ignored : {"SOFTWARE", "CAPDATE", "GMT", "FRAME"})
        if (key == ignored) return;
    std::string value = line.substr(i, end - i);
    if (std::string* old = in.find(key)) {
        if (key == "EXPOSURE")
            value = formatted("%.6e", std::atof(old->c_str()) * std::atof(value.c_str()));
        *old = value;
    } else {
        in.settings.emplace_back(key, value);
    }
}

void Comparer::identify(Input& in) {
    const std::string& d = *in.bytes;
    if (d.empty() || (d.size() == 1 && d[0] == '#'))
        throw InputError(in.name + ": unexpected end-of-file");
    if (d.size() >= 2 && d[0] == '#' && d[1] == '?') {
        in.hasHeader = true;
        size_t pos = d.find('\n', 2);
        if (pos == 2 && d.size() == 2) throw InputError(in.name + ": unexpected end-of-file");
        const std::string id = d.substr(2, pos == std::string::npos ? std::string::npos : pos - 1);
        ++in.lines;
        if (warns() && id.rfind("RADIANCE", 0) != 0)
            out_ << in.name << ": warning - unexpected header ID: " << id;
        if (pos == std::string::npos) throw InputError(in.name + ": unknown error reading header");
        ++pos;
        for (;;) {
            if (pos >= d.size()) throw InputError(in.name + ": unknown error reading header");
            size_t nl = d.find('\n', pos);
            if (nl == std::string::npos)
                throw InputError(in.name + ": unknown error reading header");
            std::string line = d.substr(pos, nl - pos);
            pos = nl + 1;
            if (line.empty() || line == "\r") break;
            setVariable(in, line);
        }
        ++in.lines;
        in.dataStart = pos;
        const std::string* f = in.find("FORMAT");
        in.kind = f ? kindOfFormat(*f) : DataKind::kUnknown;
        return;
    }
    const size_t n = std::min<size_t>(d.size(), 10240);
    in.kind = DataKind::kText;
    for (size_t i = 0; i < n; ++i) {
        const unsigned char c = static_cast<unsigned char>(d[i]);
        if (c == 0 || c > 127) {
            in.kind = DataKind::kBinary;
            break;
        }
    }
}

bool Comparer::headersMatch(Input& a, Input& b) {
    for (auto& [key, value] : a.settings) {
        const std::string* other = b.find(key);
        if (!other) {
            if (reports())
                out_ << prog_ << ": variable '" << key << "' missing in '" << b.name << "'\n";
            return false;
        }
        if (!equivalent(value.c_str(), other->c_str())) {
            if (reports()) {
                out_ << prog_ << ": header variable '" << key << "' has different values\n";
                if (verbose()) {
                    out_ << a.name << ": " << key << '=' << value << '\n';
                    out_ << b.name << ": " << key << '=' << *other << '\n';
                }
            }
            return false;
        }
    }
    const long extra = static_cast<long>(b.settings.size()) - static_cast<long>(a.settings.size());
    if (warns() && extra)
        out_ << prog_ << ": warning - '" << b.name << "' has " << extra
             << " extra header setting(s)\n";
    return true;
}

bool Comparer::realCheck(double r1, double r2) {
    double diff2 = (r1 - r2) * (r1 - r2);
    if (opt_.relMin > 0) {
        double av2 = .25 * (r1 * r1 + 2. * std::fabs(r1 * r2) + r2 * r2);
        if (av2 < opt_.relMin * opt_.relMin) av2 = opt_.relMin * opt_.relMin;
        diff2 /= av2;
    }
    if (opt_.maxLimit >= 0 && diff2 > opt_.maxLimit * opt_.maxLimit) {
        if (reports()) {
            char buf[256];
            std::snprintf(buf, sizeof buf,
                          "%s: %sdifference between %.8g and %.8g exceeds epsilon of %.8g\n",
                          prog_.c_str(), opt_.relMin > 0 ? "relative " : "", r1, r2, opt_.maxLimit);
            out_ << buf;
        }
        return false;
    }
    diff2Sum_ += diff2;
    ++nSum_;
    return true;
}

bool Comparer::goodRms(const Input& a, const Input& b) {
    if (!nSum_) return true;
    const double ms = diff2Sum_ / static_cast<double>(nSum_);
    const char* rel = opt_.relMin > 0 ? "relative " : "";
    char buf[128];
    if (ms > opt_.rmsLimit * opt_.rmsLimit) {
        if (reports()) {
            out_ << prog_ << ": " << rel << "RMS difference between '" << a.name << "' and '"
                 << b.name << "' of ";
            std::snprintf(buf, sizeof buf, "%.5g exceeds limit of %.5g\n", std::sqrt(ms),
                          opt_.rmsLimit);
            out_ << buf;
        }
        return false;
    }
    if (verbose()) {
        std::snprintf(buf, sizeof buf, "%.5g\n", std::sqrt(ms));
        out_ << prog_ << ": " << rel << "RMS difference of reals in '" << a.name << "' and '"
             << b.name << "' is " << buf;
    }
    return true;
}

bool Comparer::compareBinary(const Input& a, const Input& b) {
    if (verbose()) out_ << prog_ << ": comparing inputs as binary\n";
    const std::string& d1 = *a.bytes;
    const std::string& d2 = *b.bytes;
    size_t i = a.dataStart, j = b.dataStart;
    for (;; ++i, ++j) {
        if (i >= d1.size()) {
            if (j >= d2.size()) return true;
            if (reports()) out_ << a.name << ": unexpected end-of-file\n";
            return false;
        }
        if (j >= d2.size()) {
            if (reports()) out_ << b.name << ": unexpected end-of-file\n";
            return false;
        }
        if (d1[i] != d2[j]) break;
    }
    if (!reports()) return false;
    out_ << prog_ << ": binary files '" << a.name << "' and '" << b.name
         << "' differ at byte offset " << i + 1 << '|' << j + 1 << '\n';
    if (verbose()) {
        char buf[256];
        std::snprintf(buf, sizeof buf, "%s: byte in '%s' is 0x%X, byte in '%s' is 0x%X\n",
                      prog_.c_str(), a.name.c_str(), static_cast<unsigned char>(d1[i]),
                      b.name.c_str(), static_cast<unsigned char>(d2[j]));
        out_ << buf;
    }
    return false;
}

// The resolution line at the data start; moves dataStart past it.
Resolution readResolution(Input& in) {
    const std::string& d = *in.bytes;
    const size_t nl = d.find('\n', in.dataStart);
    std::optional<Resolution> r;
    if (nl != std::string::npos) r = parseResolution(d.substr(in.dataStart, nl - in.dataStart));
    if (!r) throw InputError(in.name + ": bad picture resolution string");
    in.dataStart = nl + 1;
    return *r;
}

bool Comparer::comparePictures(const Input& a0, const Input& b0) {
    if (verbose()) out_ << prog_ << ": comparing inputs as HDR images\n";
    Input a = a0, b = b0;
    const Resolution r1 = readResolution(a), r2 = readResolution(b);
    if (r1.yMajor != r2.yMajor || r1.xDecreasing != r2.xDecreasing ||
        r1.yDecreasing != r2.yDecreasing) {
        if (reports())
            out_ << prog_ << ": HDR images '" << a.name << "' and '" << b.name
                 << "' have different pixel ordering\n";
        return false;
    }
    if (r1.xres != r2.xres || r1.yres != r2.yres) {
        if (reports())
            out_ << prog_ << ": HDR images '" << a.name << "' and '" << b.name
                 << "' are different sizes\n";
        return false;
    }
    std::stringbuf in1(a.bytes->substr(a.dataStart), std::ios::in);
    std::stringbuf in2(b.bytes->substr(b.dataStart), std::ios::in);
    const int len = r1.scanlineLength();
    std::vector<Colr> s1(len), s2(len);
    for (int y = 0; y < r1.scanlineCount(); ++y) {
        const bool bad1 = !decodeScanline(in1, s1.data(), len).empty();
        const bool bad2 = !decodeScanline(in2, s2.data(), len).empty();
        if (bad1 || bad2) {
            if (reports()) out_ << prog_ << ": unexpected end-of-file\n";
            return false;
        }
        for (int x = 0; x < len; ++x) {
            const Pixel c1 = toPixel(s1[x]), c2 = toPixel(s2[x]);
            // The mean (summed in float, as RADIANCE's COLOR), then the largest primary of
            // the reference pixel.
            const float sum1 = c1[0] + c1[1] + c1[2], sum2 = c2[0] + c2[1] + c2[2];
            bool same = realCheck(sum1 * (1. / 3.), sum2 * (1. / 3.));
            if (same) {
                int p = c1[1] > c1[0] ? 1 : 0;
                if (c1[2] > c1[p]) p = 2;
                same = realCheck(c1[p], c2[p]);
            }
            if (same) continue;
            if (reports()) {
                out_ << prog_ << ": pixels at scanline " << y << " offset " << x << " differ\n";
                if (verbose()) {
                    char buf[128];
                    std::snprintf(buf, sizeof buf, "(R,G,B)=(%g,%g,%g)\n", c1[0], c1[1], c1[2]);
                    out_ << a.name << ": " << buf;
                    std::snprintf(buf, sizeof buf, "(R,G,B)=(%g,%g,%g)\n", c2[0], c2[1], c2[2]);
                    out_ << b.name << ": " << buf;
                }
            }
            return false;
        }
    }
    return goodRms(a, b);
}

const char* ordinalSuffix(long n) {
    static const char* s[] = {"th", "st", "nd", "rd", "th", "th", "th", "th", "th", "th"};
    return s[n % 10];  // RADIANCE's: 11st, 12nd, ...
}

template <class T>
T valueAt(const std::string& d, size_t at, bool swapped) {
    char b[sizeof(T)];
    std::memcpy(b, d.data() + at, sizeof(T));
    if (swapped)
        for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
}

template <class T>
bool Comparer::compareReals(const Input& a, const Input& b, const char* what) {
    if (verbose())
        out_ << prog_ << ": comparing inputs as "
             << (sizeof(T) == 4 ? "32-bit IEEE floats" : "64-bit IEEE doubles") << '\n';
    const size_t n1 = (a.bytes->size() - a.dataStart) / sizeof(T);
    const size_t n2 = (b.bytes->size() - b.dataStart) / sizeof(T);
    for (size_t i = 0; i < n1; ++i) {
        if (i >= n2) break;
        const double v1 = valueAt<T>(*a.bytes, a.dataStart + i * sizeof(T), a.swapped);
        const double v2 = valueAt<T>(*b.bytes, b.dataStart + i * sizeof(T), b.swapped);
        if (realCheck(v1, v2)) continue;
        const long k = static_cast<long>(i) + 1;
        if (reports())
            out_ << prog_ << ": " << k << ordinalSuffix(k) << ' ' << what << " values differ\n";
        return false;
    }
    if (n1 == n2) return goodRms(a, b);
    if (reports()) out_ << prog_ << ": unexpected end-of-file\n";
    return false;
}

int Comparer::run(Input& a, Input& b) {
    identify(a);
    identify(b);
    if (a.kind != b.kind) {
        if (reports())
            out_ << prog_ << ": '" << a.name << "' format is " << kindName(a.kind) << " and '"
                 << b.name << "' is " << kindName(b.kind) << '\n';
        return 1;
    }
    const bool ignore =
        opt_.ignoreHeader || a.kind == DataKind::kText || a.kind == DataKind::kBinary;
    if (!ignore && !headersMatch(a, b)) return 1;
    if (!ignore && warns()) {
        if (a.lines != b.lines) out_ << prog_ << ": warning - headers are different lengths\n";
        if (a.kind == DataKind::kUnknown) out_ << prog_ << ": warning - unrecognized format\n";
    }
    const bool realData = a.kind == DataKind::kFloat || a.kind == DataKind::kDouble;
    if (verbose()) {
        out_ << prog_ << ": data format is " << kindName(a.kind) << '\n';
        if (realData) {
            if (a.swapped) out_ << prog_ << ": input '" << a.name << "' is byte-swapped\n";
            if (b.swapped) out_ << prog_ << ": input '" << b.name << "' is byte-swapped\n";
        }
    }
    if (!realData) a.swapped = b.swapped = false;
    bool same = false;
    switch (a.kind) {
        case DataKind::kText:
        case DataKind::kAscii:
            same = compareText(a, b);
            break;
        case DataKind::kRgbe:
        case DataKind::kXyze:
            same = comparePictures(a, b);
            break;
        case DataKind::kFloat:
            same = compareReals<float>(a, b, "float");
            break;
        case DataKind::kDouble:
            same = compareReals<double>(a, b, "double");
            break;
        default:
            same = compareBinary(a, b);
            break;
    }
    return same ? 0 : 1;
}

std::string readAll(std::istream& in) {
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace radcompare_detail

using namespace radcompare_detail;

OptionTable radcompareTable(RadcompareOptions& o) {
    OptionTable t;
    t.add(customOption(prefix("-h"), "-h",
                       [&o](OptionReader&) { o.ignoreHeader = !o.ignoreHeader; }));
    t.add(customOption(prefix("-c"), "-c", [&o](OptionReader& r) { o.comment = r.option()[2]; }));
    t.add(customOption(prefix("-s"), "-s",
                       [&o](OptionReader&) { o.report = CompareReport::kQuiet; }));
    t.add(customOption(prefix("-w"), "-w", [&o](OptionReader&) {
        if (o.report > CompareReport::kErrors) o.report = CompareReport::kErrors;
    }));
    t.add(customOption(prefix("-v"), "-v",
                       [&o](OptionReader&) { o.report = CompareReport::kVerbose; }));
    // RADIANCE reads the values with atof: a word that is no number is 0.
    auto real = [](OptionReader& r) { return std::atof(r.word().c_str()); };
    t.add(customOption(prefix("-m"), "-max", [&o, real](OptionReader& r) { o.maxLimit = real(r); }),
          [&o] { return formatLine("-max %g\t\t\t\t# largest difference\n", o.maxLimit); });
    t.add(
        customOption(prefix("-re"), "-rel", [&o, real](OptionReader& r) { o.relMin = real(r); }),
        [&o] { return formatLine("-rel %g\t\t\t\t# relative below this magnitude\n", o.relMin); });
    t.add(
        customOption(prefix("-rm"), "-rms", [&o, real](OptionReader& r) { o.rmsLimit = real(r); }),
        [&o] { return formatLine("-rms %g\t\t\t\t# RMS difference limit\n", o.rmsLimit); });
    t.messages.unknown = [](const std::string&) { return std::string(); };
    t.messages.missing = [](const std::string&) { return std::string(); };
    return t;
}

RadcompareOptions parseRadcompareArgs(std::vector<std::string> args) {
    static const char* usage =
        "usage: radcompare [-h][-c#][-s|-w|-v][-rel min_test][-rms epsilon][-max epsilon] "
        "reference test";
    RadcompareOptions o;
    const OptionTable t = radcompareTable(o);
    size_t next = 0;
    try {
        next = t.parse(args, 0).next;
    } catch (const InputError&) {
        throw InputError(usage);
    }
    if (next < args.size() && args[next] == "-") o.firstFromStdin = true;
    if (next + 2 != args.size()) throw InputError(usage);
    o.reference = args[next];
    o.test = args[next + 1];
    return o;
}

int compareRadianceData(const RadcompareOptions& opt, const std::string& name1,
                        const std::string& data1, const std::string& name2,
                        const std::string& data2, std::ostream& out, const std::string& program) {
    Input a, b;
    a.name = name1;
    a.bytes = &data1;
    b.name = name2;
    b.bytes = &data2;
    return Comparer(opt, out, program).run(a, b);
}

int runRadcompare(const RadcompareOptions& opt, std::istream& stdinStream, std::ostream& out) {
    if (opt.reference == opt.test) {
        if (opt.report >= CompareReport::kWarnings)
            out << "radcompare: warning - identical inputs given\n";
        return 0;
    }
    auto load = [&](const std::string& path, bool fromStdin, std::string& name) {
        if (fromStdin) {
            name = "<stdin>";
            return readAll(stdinStream);
        }
        name = path;
        std::ifstream f(path, std::ios::binary);
        if (!f) throw InputError(path + ": cannot open for reading");
        return readAll(f);
    };
    std::string n1, n2;
    const std::string d1 = load(opt.reference, opt.firstFromStdin, n1);
    const std::string d2 = load(opt.test, opt.test == "-", n2);
    return compareRadianceData(opt, n1, d1, n2, d2, out);
}

}  // namespace rp
