// rpict's frames, output files and recovery (see rpict_run.h).
#include "render/rpict_run.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <vector>

#include "image/picture.h"
#include "image/rgbe.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::render {

std::string frameFileName(const std::string& pattern, int frame) {
    std::string out;
    bool used = false;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        size_t j = i + 1;
        bool left = false, zero = false;
        for (; j < pattern.size() && (pattern[j] == '-' || pattern[j] == '0'); ++j)
            (pattern[j] == '-' ? left : zero) = true;
        int width = 0;
        for (; j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])); ++j)
            width = std::min(width * 10 + (pattern[j] - '0'), 64);
        if (used || j >= pattern.size() || (pattern[j] != 'd' && pattern[j] != 'i'))
            throw InputError("bad frame number field in \"" + pattern +
                             "\" (one integer field such as %03d expected)");
        used = true;
        std::string digits = std::to_string(frame < 0 ? -int64_t(frame) : int64_t(frame));
        const std::string sign = frame < 0 ? "-" : "";
        const size_t len = sign.size() + digits.size();
        const size_t pad = size_t(width) > len ? size_t(width) - len : 0;
        if (left)
            out += sign + digits + std::string(pad, ' ');
        else if (zero)
            out += sign + std::string(pad, '0') + digits;
        else
            out += std::string(pad, ' ') + sign + digits;
        i = j;
    }
    return out;
}

namespace {

bool isInteger(const std::string& s) {
    size_t i = (!s.empty() && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
    if (i >= s.size()) return false;
    for (; i < s.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
    return true;
}

// Where a picture goes: standard output or an exclusively created file; every write is
// flushed so that an interrupted run leaves whole scanlines behind.
class PictureOutput {
public:
    explicit PictureOutput(std::ostream& out) : stream_(&out) {}
    PictureOutput(std::FILE* file, std::string name) : file_(file), name_(std::move(name)) {}
    ~PictureOutput() {
        if (file_) std::fclose(file_);
    }
    PictureOutput(const PictureOutput&) = delete;
    PictureOutput& operator=(const PictureOutput&) = delete;

    void write(const std::string& data) {
        if (file_) {
            if (std::fwrite(data.data(), 1, data.size(), file_) != data.size() ||
                std::fflush(file_) != 0)
                throw InputError("write error on \"" + name_ + "\"");
        } else {
            stream_->write(data.data(), std::streamsize(data.size()));
            stream_->flush();
            if (!*stream_) throw InputError("write error on standard output");
        }
    }
    void close() {
        if (file_ && std::fclose(file_) != 0) {
            file_ = nullptr;
            throw InputError("write error on \"" + name_ + "\"");
        }
        file_ = nullptr;
    }

private:
    std::ostream* stream_ = nullptr;
    std::FILE* file_ = nullptr;
    std::string name_;
};

// The z-file: raw floats, one per pixel, top row first (RADIANCE's layout). When
// recovering it is opened without truncation and written from the first missing row on,
// as RADIANCE's render() seeks into it.
class DepthOutput {
public:
    DepthOutput(const std::string& name, size_t firstPixel) : name_(name) {
        if (firstPixel > 0) file_ = std::fopen(name.c_str(), "r+b");
        if (!file_) file_ = std::fopen(name.c_str(), "wb");
        if (!file_) throw InputError("cannot open z-file \"" + name + "\"");
        if (firstPixel > 0 && std::fseek(file_, long(firstPixel * sizeof(float)), SEEK_SET) != 0)
            throw InputError("z-file seek error on \"" + name + "\"");
    }
    ~DepthOutput() {
        if (file_) std::fclose(file_);
    }
    DepthOutput(const DepthOutput&) = delete;
    DepthOutput& operator=(const DepthOutput&) = delete;

    void write(const float* z, size_t n) {
        if (std::fwrite(z, sizeof(float), n, file_) != n || std::fflush(file_) != 0)
            throw InputError("write error on z-file \"" + name_ + "\"");
    }
    void close() {
        std::FILE* f = file_;
        file_ = nullptr;
        if (std::fclose(f) != 0) throw InputError("write error on z-file \"" + name_ + "\"");
    }

private:
    std::string name_;
    std::FILE* file_ = nullptr;
};

// What an interrupted picture holds (RADIANCE's viewfile + salvage).
struct RecoverFile {
    bool viewOk = false;  // the header gave a view and the resolution line a size
    View view;
    int xres = 0, yres = 0;
};

// Reads the header's views (applied on top of `view`) and the size, as RADIANCE's
// viewfile; nullopt when the file cannot be opened or has no picture header.
std::optional<RecoverFile> readRecoverHeader(const std::string& path, const View& view) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    try {
        PictureInfo info = readPictureInfo(in, path);
        RecoverFile r;
        r.view = view;
        int n = 0;
        for (const auto& line : info.header.lines)
            if (isViewLine(line)) n += applyViewString(r.view, line);
        const Resolution& res = info.resolution;
        const bool standard = res.yMajor && res.yDecreasing && !res.xDecreasing;
        r.viewOk = n > 0 && standard;
        r.xres = standard ? res.xres : 0;
        r.yres = standard ? res.yres : 0;
        return r;
    } catch (const InputError&) {
        return std::nullopt;
    }
}

// Copies the complete scanlines of the interrupted picture to `out` (after the new
// header) and returns how many there were; removes the file when done, as RADIANCE's
// salvage. A file that cannot be read as a picture is left alone with a warning.
int salvage(const std::string& path, int xres, int yres, PictureOutput& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        warn("cannot open recover file \"" + path + "\"");
        return 0;
    }
    PictureInfo info;
    try {
        info = readPictureInfo(in, path);
    } catch (const InputError&) {
        warn("bad recover file \"" + path + "\" - not removed");
        return 0;
    }
    const Resolution& res = info.resolution;
    if (!(res.yMajor && res.yDecreasing && !res.xDecreasing)) {
        warn("bad recover file \"" + path + "\" - not removed");
        return 0;
    }
    if (res.xres != xres || res.yres != yres)
        throw InputError("resolution mismatch in recover file \"" + path + "\"");
    std::vector<Colr> scan(static_cast<size_t>(xres));
    std::string data;
    int rows = 0;
    for (; rows < yres; ++rows) {
        if (!decodeScanline(*in.rdbuf(), scan.data(), xres).empty()) break;
        encodeScanline(scan.data(), xres, data);
    }
    out.write(data);
    in.close();
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return rows;
}

// RADIANCE compat (rpict.c rpict): -r names the -o file: move it out of the way first
// (RADIANCE's "rfXXXXXX" beside it). Returns the new name, or "" with a warning when
// there is nothing to recover.
std::string moveAside(const std::string& name) {
    std::filesystem::path p(name);
    std::string temp = (p.parent_path() / "rfXXXXXX").string();
    std::vector<char> buf(temp.begin(), temp.end());
    buf.push_back('\0');
    const int fd = mkstemp(buf.data());
    if (fd < 0) throw InputError("cannot rename \"" + name + "\" (no temporary name)");
    ::close(fd);
    temp = buf.data();
    if (std::rename(name.c_str(), temp.c_str()) != 0) {
        const int err = errno;
        std::remove(temp.c_str());
        if (err == ENOENT) {
            warn("new output file \"" + name + "\"");
            return "";
        }
        throw InputError("cannot rename \"" + name + "\" to \"" + temp + "\"");
    }
    return temp;
}

}  // namespace

int runRpict(const RpictOptions& options, const PixelTracerFactory& factory,
             const ProgressCallback& progress, RpictIo& io) {
    if (distributed(io.cluster)) {
        // Sequences and recovery decide per frame from files only the root sees.
        if (options.sequenceStart > 0 || !options.recoverFile.empty())
            throw InputError("-S and -r render in one process, not across MPI ranks");
        if (!io.cluster->isRoot()) {
            RenderRows rows;
            rows.cluster = io.cluster;
            std::vector<float> depth;
            renderPicture(options, factory, {}, options.zFile.empty() ? nullptr : &depth, rows);
            return 0;
        }
    }
    int seq = std::max(0, options.sequenceStart);
    std::string recover = options.recoverFile;
    View view = options.view, lastView = options.view;
    // RADIANCE compat (rpict.c nextview): the next input line that carries a view.
    auto nextView = [&]() -> bool {
        lastView = view;
        if (!io.views) return false;
        for (std::string line; std::getline(*io.views, line);) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            if (isViewLine(line) && applyViewString(view, line) > 0) return true;
        }
        return false;
    };
    if (seq > 0 && !recover.empty() && isInteger(recover)) {
        const int frame = std::stoi(recover);
        if (frame < seq) throw InputError("recover frame less than start frame");
        if (options.outputFile.empty()) throw InputError("missing output file specification");
        for (; seq < frame; ++seq)
            if (!nextView()) throw InputError("unexpected EOF on view input");
        ViewRays check(view);
        recover = frameFileName(options.outputFile, seq);
    }
    if (!options.outputFile.empty() && !recover.empty() &&
        frameFileName(options.outputFile, seq) == recover)
        recover = moveAside(recover);

    int pictures = 0;
    do {
        if (seq && !nextView()) break;
        std::unique_ptr<PictureOutput> out;
        if (!options.outputFile.empty()) {
            const std::string name = frameFileName(options.outputFile, seq);
            errno = 0;
            std::FILE* f = std::fopen(name.c_str(), "wbx");  // exclusive, as RADIANCE's
            if (!f) {
                if (errno != EEXIST || !recover.empty() || name == options.outputFile)
                    throw InputError("cannot open output file \"" + name + "\"");
                ViewRays check(view);
                continue;  // RADIANCE compat: an existing frame is not clobbered
            }
            out = std::make_unique<PictureOutput>(f, name);
        } else {
            RP_CHECK(io.out != nullptr);
            out = std::make_unique<PictureOutput>(*io.out);
        }
        RpictOptions frame = options;
        frame.view = view;
        if (!recover.empty()) {
            auto r = readRecoverHeader(recover, view);
            if (!r || !r->viewOk) {
                warn("cannot recover view parameters from \"" + recover + "\"");
            } else {
                frame.view = r->view;
                frame.xres = r->xres;
                frame.yres = r->yres;
                frame.pixelAspect = 0;  // keep the recovered size
            }
        }
        ViewRays check(frame.view);
        const PictureSize size = pictureSize(frame);
        if (seq && io.frameStarted) io.frameStarted(seq, frame.view);

        Picture head;
        head.header.lines = viewHeaderLines(frame);
        if (seq) head.header.lines.insert(head.header.lines.begin(), fmt::format("FRAME={}", seq));
        addRpictHeader(head, io.commandLine, io.clock());
        head.header.lines.push_back(std::string("FORMAT=") + kRgbeFormat);
        std::ostringstream hs;
        writeHeader(hs, head.header);
        Resolution res;
        res.xres = size.xres;
        res.yres = size.yres;
        hs << formatResolution(res) << '\n';
        out->write(hs.str());

        const int firstRow = recover.empty() ? 0 : salvage(recover, size.xres, size.yres, *out);
        std::unique_ptr<DepthOutput> zout;
        if (!options.zFile.empty())
            zout = std::make_unique<DepthOutput>(frameFileName(options.zFile, seq),
                                                 size_t(firstRow) * size_t(size.xres));
        RenderRows rows;
        rows.cluster = io.cluster;
        rows.firstRow = firstRow;
        rows.previousView = seq ? &lastView : nullptr;
        std::vector<Colr> scan(size_t(size.xres));
        rows.done = [&](const Picture& pic, const std::vector<float>& z, int begin, int end) {
            // Depths first, as RADIANCE's render(): a picture row is never ahead of its z.
            if (zout)
                zout->write(z.data() + size_t(begin) * size_t(size.xres),
                            size_t(end - begin) * size_t(size.xres));
            std::string data;
            for (int y = begin; y < end; ++y) {
                for (int x = 0; x < size.xres; ++x) scan[size_t(x)] = toColr(pic.at(x, y));
                encodeScanline(scan.data(), size.xres, data);
            }
            out->write(data);
        };
        if (io.finishRows) rows.finish = io.finishRows(frame);
        std::vector<float> depth;
        renderPicture(frame, factory, progress, zout ? &depth : nullptr, rows);
        if (zout) zout->close();
        out->close();
        recover.clear();
        ++pictures;
    } while (seq++);
    if (pictures == 0) warn("no output produced");
    return pictures;
}

}  // namespace rp::render
