// total's computation (see total.h), RADIANCE total.c's execute, getrecord and putrecord.
#include "data/total.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace rp::data {
namespace {

// RADIANCE init_val: the start of each tally, and an empty ASCII field's value.
double initialValue(TotalOptions::Func f) {
    switch (f) {
        case TotalOptions::Func::Add:
            return 0.;
        case TotalOptions::Func::Multiply:
            return 1.;
        case TotalOptions::Func::Max:
            return -1e12;
        case TotalOptions::Func::Min:
            return 1e12;
    }
    return 0.;
}

constexpr std::size_t kLineBuffer = 16 * kTotalMaxColumns;  // RADIANCE's fgets buffer

}  // namespace

int Total::readRecord(std::istream& in, double* field) {
    auto* sb = in.rdbuf();
    if (o_.binaryColumns != 0) {  // RADIANCE getbinary: complete values only
        const bool dbl = o_.binaryColumns > 0;
        const std::size_t size = dbl ? sizeof(double) : sizeof(float);
        const std::size_t want = static_cast<std::size_t>(std::abs(o_.binaryColumns));
        char buf[sizeof(double) * kTotalMaxColumns];
        const std::size_t got =
            static_cast<std::size_t>(sb->sgetn(buf, static_cast<std::streamsize>(want * size)));
        const std::size_t n = got / size;
        for (std::size_t i = 0; i < n; ++i) {
            if (dbl) {
                std::memcpy(&field[i], buf + i * size, size);
            } else {
                float f;
                std::memcpy(&f, buf + i * size, size);
                field[i] = f;
            }
        }
        return static_cast<int>(n);
    }
    std::string& line = line_;  // one fgets: through the newline, or a full buffer
    line.clear();
    for (int c; line.size() < kLineBuffer - 1 && (c = sb->sbumpc()) != EOF;) {
        line += static_cast<char>(c);
        if (c == '\n') break;
    }
    if (line.empty()) return 0;
    char* cp = line.data();
    const bool whiteTab = std::isspace(static_cast<unsigned char>(o_.separator)) != 0;
    int nf;
    for (nf = 0; nf < kTotalMaxColumns; ++nf) {
        while (std::isspace(static_cast<unsigned char>(*cp))) ++cp;
        if (!*cp) break;
        char* num = cp;
        while (*cp && !(whiteTab ? std::isspace(static_cast<unsigned char>(*cp)) != 0
                                 : *cp == o_.separator))
            ++cp;
        if (*cp) *cp++ = '\0';
        // RADIANCE compat: an empty field (two separators) counts as the tally's start.
        if (!*num || std::isspace(static_cast<unsigned char>(*num)))
            field[nf] = initialValue(o_.func);
        else
            field[nf] = std::atof(num);
    }
    return nf;
}

void Total::writeRecord(const double* field, int n, std::ostream& out) {
    if (o_.binaryOutput > 0) {
        out.write(reinterpret_cast<const char*>(field),
                  static_cast<std::streamsize>(n * sizeof(double)));
        return;
    }
    if (o_.binaryOutput < 0) {
        for (int i = 0; i < n; ++i) {
            const float f = static_cast<float>(field[i]);
            out.write(reinterpret_cast<const char*>(&f), sizeof f);
        }
        return;
    }
    std::string s;
    char buf[64];
    for (int i = 0; i < n; ++i) {
        s.append(buf, static_cast<std::size_t>(std::snprintf(buf, sizeof buf, "%.9g", field[i])));
        if (i + 1 < n) s += o_.separator;
    }
    s += '\n';
    out.write(s.data(), static_cast<std::streamsize>(s.size()));
    if (!o_.subtotal) out.flush();
}

bool Total::run(std::istream& in, std::ostream& out) {
    using Func = TotalOptions::Func;
    std::vector<double> input(kTotalMaxColumns), tally(kTotalMaxColumns), result(kTotalMaxColumns);
    std::vector<short> sign(kTotalMaxColumns);
    long total = 0;
    int touched = kTotalMaxColumns;  // columns changed since the tallies were reset
    for (;;) {
        if (total == 0) {  // columns beyond `touched` still hold their start values
            for (int n = 0; n < touched; ++n) {
                tally[n] = o_.func == Func::Multiply ? 0. : initialValue(o_.func);
                sign[n] = 1;
            }
            touched = 0;
        }
        int ncol = 0;
        long nlin = 0;
        for (int nread;
             (o_.count <= 0 || nlin < o_.count) && (o_.inputLimit <= 0 || nlin < o_.inputLimit) &&
             (nread = readRecord(in, input.data())) > 0;
             ++nlin) {
            for (int n = 0; n < nread; ++n) {
                double& v = input[n];
                switch (o_.func) {
                    case Func::Add:
                        if (v == 0.0) break;
                        tally[n] += o_.power != 0.0 ? std::pow(std::fabs(v), o_.power) : v;
                        break;
                    case Func::Multiply:  // a sum of logarithms, and the sign apart
                        if (v == 0.0) {
                            sign[n] = 0;
                        } else if (v < 0.0) {
                            sign[n] = static_cast<short>(-sign[n]);
                            v = -v;
                        }
                        if (sign[n]) tally[n] += std::log(v);
                        break;
                    case Func::Max:
                        if (v > tally[n]) tally[n] = v;
                        break;
                    case Func::Min:
                        if (v < tally[n]) tally[n] = v;
                        break;
                }
            }
            if (nread > ncol) ncol = nread;
            if (nread > touched) touched = nread;
        }
        if (nlin == 0) break;  // end of input, or a second blank line
        total += nlin;
        for (int n = 0; n < ncol; ++n) {
            result[n] = tally[n];
            if (o_.mean) {
                result[n] /= static_cast<double>(total);
                if (o_.func == Func::Add && o_.power != 0.0 && result[n] != 0.0)
                    result[n] = std::pow(result[n], 1.0 / o_.power);
            }
            if (o_.func == Func::Multiply) result[n] = sign[n] * std::exp(result[n]);
        }
        writeRecord(result.data(), ncol, out);
        ++recordsOut_;
        if (done()) return false;
        if (!o_.subtotal) total = 0;
        if (o_.inputLimit > 0 && nlin >= o_.inputLimit) break;
    }
    return !done();
}

}  // namespace rp::data
