// See rlam.h.
#include "data/rlam.h"

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "util/error.h"

namespace rp::data {

void RlamState::setFormat(const std::string& format) {
    const char c = format.empty() ? '\0' : format[0];
    int bytes = 0;
    switch (c) {
        case 'f':
        case 'F':
            bytes = sizeof(float);
            break;
        case 'd':
        case 'D':
            bytes = sizeof(double);
            break;
        case 'i':
        case 'I':
            bytes = 4;
            break;
        case 'w':
        case 'W':
            bytes = 2;
            break;
        case 'b':
            bytes = 1;
            break;
        case 'a':
            // RADIANCE compat: "-ia" with anything after it counts lines, "-ia1" is "-ia".
            bytes = format.size() > 1 ? -1 : 0;
            break;
        default:
            throw InputError("bad option '-i" + format + "'");
    }
    if (format.size() > 1 && std::isdigit(static_cast<unsigned char>(format[1])))
        bytes *= std::atoi(format.c_str() + 1);
    if (bytes == -1) bytes = 0;
    if (bytes > kRlamMaxLine) throw InputError("input size too big");
    recordBytes = bytes;
    if (bytes > 0) {
        separator.clear();
        binaryOutput = true;
    }
}

namespace {

// One line as RADIANCE reads it (fgets into a MAXLINE buffer) without its last
// character. RADIANCE compat: the last character goes even when it is not a newline
// (a file's unterminated last line loses it), and a longer line is read in pieces.
bool readLine(std::FILE* f, char* buf) {
    if (!std::fgets(buf, kRlamMaxLine, f)) return false;
    const size_t n = std::strlen(buf);
    if (n > 0) buf[n - 1] = '\0';
    return true;
}

}  // namespace

RlamResult laminate(const std::vector<RlamStream>& streams, long limit, bool unbuffered,
                    std::FILE* out) {
    RlamResult result;
    std::unique_ptr<char[]> buf(new char[kRlamMaxLine]);
    bool ascii = false;
    for (const RlamStream& s : streams) ascii = ascii || s.input->recordBytes <= 0;
    long left = limit;
    for (;;) {
        bool complete = true;
        for (size_t i = 0; i < streams.size() && complete; ++i) {
            std::FILE* f = streams[i].file;
            const RlamInput& in = *streams[i].input;
            if (in.recordBytes > 0) {
                if (std::fread(buf.get(), size_t(in.recordBytes), 1, f) != 1 ||
                    std::fwrite(buf.get(), size_t(in.recordBytes), 1, out) != 1)
                    complete = false;
                continue;
            }
            const int lines = in.recordBytes < 0 ? -in.recordBytes : 1;
            for (int k = 0; k < lines; ++k) {
                if (!readLine(f, buf.get())) {
                    complete = false;
                    break;
                }
                if (i > 0 || k > 0) std::fputs(in.separator.c_str(), out);
                if (std::fputs(buf.get(), out) == EOF) {
                    complete = false;
                    break;
                }
            }
        }
        if (!complete) break;
        if (ascii) std::putc('\n', out);
        if (unbuffered) std::fflush(out);
        // RADIANCE compat: a limit of 0 or below reads to the end.
        if (--left == 0) break;
    }
    result.writeError = std::fflush(out) == EOF;
    result.premature = left > 0;
    return result;
}

RlamResult rlam(const std::vector<RlamInput>& inputs, long limit, bool unbuffered, std::FILE* out) {
    if (inputs.empty()) throw InputError("no input streams");
    struct Opened {
        std::FILE* file = nullptr;
        bool command = false;
    };
    std::vector<Opened> opened;
    auto closeAll = [&opened] {
        for (Opened& o : opened) {
            if (o.command)
                pclose(o.file);
            else if (o.file != stdin)
                std::fclose(o.file);
        }
        opened.clear();
    };
    std::vector<RlamStream> streams;
    try {
        for (const RlamInput& in : inputs) {
            Opened o;
            if (in.name == "-") {
                o.file = stdin;
            } else if (!in.name.empty() && in.name[0] == '!') {
                std::fflush(nullptr);
                o.file = popen(in.name.c_str() + 1, "r");
                o.command = true;
                if (!o.file) throw InputError(in.name + ": cannot start command");
            } else {
                o.file = std::fopen(in.name.c_str(), "rb");
                if (!o.file) throw InputError(in.name + ": cannot open file");
            }
            opened.push_back(o);
            streams.push_back({o.file, &in});
        }
        const RlamResult r = laminate(streams, limit, unbuffered, out);
        closeAll();
        if (r.writeError) throw InputError("write error on standard output");
        return r;
    } catch (...) {
        closeAll();
        throw;
    }
}

}  // namespace rp::data
