// Reading matrix inputs (see matrix_input.h).
#include "matrix/matrix_input.h"

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <iterator>

#include "util/error.h"
#include "util/file_read.h"

namespace rp::matrix {

namespace {

std::string readCommand(const std::string& spec) {
    const std::string command = spec.substr(1);
    std::cout.flush();  // the command may write to our standard output too
    FILE* p = popen(command.c_str(), "r");
    if (!p) throw InputError(SourceLoc{spec, 0}, "cannot run command");
    std::string bytes;
    char buf[65536];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) bytes.append(buf, n);
    const int status = pclose(p);
    // RADIANCE compat (cmatrix.c cm_load): a failing command is only a warning there, and
    // rmx_load does not look; we refuse its output, which is usually incomplete.
    if (status != 0) {
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        throw InputError(SourceLoc{spec, 0},
                         "command failed (exit status " + std::to_string(code) + ")");
    }
    return bytes;
}

bool isWordSpace(char c) { return c == '\0' || std::isspace(static_cast<unsigned char>(c)); }

}  // namespace

InputData readInput(const std::string& spec) {
    if (spec.empty() || spec == "-" || spec == kStdinName) {
        std::cout.flush();
        std::string bytes((std::istreambuf_iterator<char>(std::cin)),
                          std::istreambuf_iterator<char>());
        return {kStdinName, std::move(bytes)};
    }
    if (spec[0] == '!') return {spec, readCommand(spec)};
    return {spec, readFileBytes(spec)};
}

bool DataReader::readHeader(std::vector<std::string>& lines) {
    const std::string& b = in_.bytes;
    if (pos_ >= b.size() || !std::isprint(static_cast<unsigned char>(b[pos_]))) return false;
    for (;;) {
        const size_t nl = b.find('\n', pos_);
        if (nl == std::string::npos) return false;
        std::string line = b.substr(pos_, nl + 1 - pos_);
        pos_ = nl + 1;
        if (line == "\n" || line == "\r\n") return true;
        lines.push_back(std::move(line));
    }
}

bool DataReader::readResolution(int& scanLength, int& scanCount) {
    // RADIANCE compat (resolu.c str2resolu): "[+-][XY] n [+-][YX] m", the first pair
    // giving the number of scanlines.
    const size_t nl = in_.bytes.find('\n', pos_);
    if (nl == std::string::npos) return false;
    const std::string line = in_.bytes.substr(pos_, nl - pos_);
    char s1, a1, s2, a2;
    int n1, n2;
    if (std::sscanf(line.c_str(), " %c%c %d %c%c %d", &s1, &a1, &n1, &s2, &a2, &n2) != 6)
        return false;
    const bool signs = (s1 == '-' || s1 == '+') && (s2 == '-' || s2 == '+');
    const bool axes = (a1 == 'X' && a2 == 'Y') || (a1 == 'Y' && a2 == 'X');
    if (!signs || !axes || n1 <= 0 || n2 <= 0) return false;
    scanCount = n1;
    scanLength = n2;
    pos_ = nl + 1;
    return true;
}

bool DataReader::skipSpaceToWord(size_t& start, size_t& end) {
    const std::string& b = in_.bytes;
    while (pos_ < b.size() && std::isspace(static_cast<unsigned char>(b[pos_]))) ++pos_;
    if (pos_ >= b.size()) return false;
    start = pos_;
    end = start;
    while (end < b.size() && !isWordSpace(b[end])) ++end;
    return true;
}

template <class T>
bool DataReader::nextNumber(T& v, T (*convert)(const char*, char**)) {
    size_t start, end;
    if (!skipSpaceToWord(start, end)) return false;
    char* stop = nullptr;
    v = convert(in_.bytes.c_str() + start, &stop);
    if (stop == in_.bytes.c_str() + start)
        throw InputError(
            SourceLoc{in_.name, line()},
            "bad number '" + in_.bytes.substr(start, std::min<size_t>(end - start, 40)) + "'");
    pos_ = static_cast<size_t>(stop - in_.bytes.c_str());
    lastWord_ = start;
    return true;
}

bool DataReader::nextDouble(double& v) { return nextNumber<double>(v, &std::strtod); }

bool DataReader::nextFloat(float& v) { return nextNumber<float>(v, &std::strtof); }

void checkDeclaredSize(const DataReader& r, int64_t rows, int64_t cols, int64_t comps) {
    const double values = double(rows) * double(cols) * double(comps);
    const double bound = 2048.0 * double(r.remaining()) + 1024;
    if (rows < 0 || cols < 0 || comps < 0 || values > double(int64_t(1) << 31) || values > bound)
        throw InputError(SourceLoc{r.name(), r.line()},
                         "header declares " + std::to_string(rows) + "x" + std::to_string(cols) +
                             "x" + std::to_string(comps) + " values, but only " +
                             std::to_string(r.remaining()) + " bytes of data follow");
}

bool DataReader::atEndIgnoringSpace() const {
    for (size_t i = pos_; i < in_.bytes.size(); ++i)
        if (!std::isspace(static_cast<unsigned char>(in_.bytes[i]))) return false;
    return true;
}

bool DataReader::readBytes(void* dst, size_t n) {
    if (remaining() < n) return false;
    std::memcpy(dst, in_.bytes.data() + pos_, n);
    pos_ += n;
    return true;
}

int DataReader::lineAt(size_t pos) const {
    const auto end =
        in_.bytes.begin() + static_cast<std::ptrdiff_t>(std::min(pos, in_.bytes.size()));
    return 1 + static_cast<int>(std::count(in_.bytes.begin(), end, '\n'));
}

void swapBytes(void* data, size_t size, size_t count) {
    auto* p = static_cast<unsigned char*>(data);
    for (size_t i = 0; i < count; ++i, p += size) std::reverse(p, p + size);
}

}  // namespace rp::matrix
