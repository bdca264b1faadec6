// rcontrib's outputs (see rcontrib_output.h).
#include "render/rcontrib_output.h"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include "image/spectral_picture.h"
#include "render/rtrace_io.h"
#include "render/rtrace_options.h"
#include "util/colr.h"
#include "util/error.h"
#include "util/header.h"
#include "util/warnings.h"

namespace rp::render {

namespace {

// Bytes of one bin's value of n samples (RADIANCE 6: n+1 byte common-exponent pixels for
// -fc with more than 3).
size_t valueSize(char format, size_t n) {
    switch (format) {
        case 'f':
            return n * sizeof(float);
        case 'd':
            return n * sizeof(double);
        case 'c':
            return n == 3 ? 4 : n + 1;
        default:
            return 0;
    }
}

}  // namespace

bool contribOutputName(const std::string& spec, const std::string& modifier, int bin,
                       std::string& name, bool& hasModifier, bool& hasBin) {
    // RADIANCE compat (rc2.c ofname): one %s and one integer conversion at most, in
    // either order, with optional width digits; %% is a literal percent.
    hasModifier = hasBin = false;
    name.clear();
    for (size_t i = 0; i < spec.size(); ++i) {
        if (spec[i] != '%') {
            name += spec[i];
            continue;
        }
        size_t j = i + 1;
        while (j < spec.size() && std::isdigit(static_cast<unsigned char>(spec[j]))) ++j;
        if (j >= spec.size()) return false;
        const std::string width = spec.substr(i + 1, j - i - 1);
        const char c = spec[j];
        char buf[64];
        if (c == '%') {
            name += '%';
        } else if (c == 's') {
            if (hasModifier) return false;
            hasModifier = true;
            std::string fmt = "%" + width + "s";
            std::snprintf(buf, sizeof buf, fmt.c_str(), modifier.c_str());
            name += modifier.size() + 64 > sizeof buf ? modifier : std::string(buf);
        } else if (c == 'd' || c == 'i' || c == 'o' || c == 'x' || c == 'X') {
            if (hasBin) return false;
            hasBin = true;
            std::string fmt = "%" + width + c;
            std::snprintf(buf, sizeof buf, fmt.c_str(), bin);
            name += buf;
        } else {
            return false;
        }
        i = j;
    }
    return true;
}

struct ContribOutput::Stream {
    std::string name;  // "" for standard output
    bool pipe = false;
    bool hasModifier = false, hasBin = false;
    std::string modifier;  // of its first value (MODIFIER= line)
    int bin = 0;           // BIN= line
    int reclen = 0;        // values per record
    FILE* file = nullptr;  // files and pipes
    bool opened = false;
    std::string buffer;  // pending bytes

    void write(std::ostream& out) {
        if (buffer.empty()) return;
        if (name.empty()) {
            out.write(buffer.data(), std::streamsize(buffer.size()));
        } else if (std::fwrite(buffer.data(), 1, buffer.size(), file) != buffer.size()) {
            throw InputError("write error on file '" + name + "'");
        }
        buffer.clear();
    }
};

ContribOutput::ContribOutput(const RcontribOptions& o, std::vector<std::string> sceneHeader,
                             std::ostream& stdoutStream)
    : o_(o),
      sceneHeader_(std::move(sceneHeader)),
      stdout_(stdoutStream),
      sampling_(spectral::makeSampling(o.render.spectralSamples, o.render.wavelengthA,
                                       o.render.wavelengthB)
                    .value_or(spectral::SamplingChoice{})
                    .sampling) {  // checked (and warned about) by the tool
    passes_ = spectral::passesOf(sampling_);
    std::map<std::string, size_t> byName;
    auto streamFor = [&](const std::string& spec, const std::string& mod, int bin,
                         bool& exists) -> size_t {
        std::string name;
        bool hasMod = false, hasBin = false;
        if (!spec.empty() && !contribOutputName(spec, mod, bin, name, hasMod, hasBin))
            throw InputError("bad output format '" + spec + "'");
        auto [it, fresh] = byName.try_emplace(name, streams_.size());
        exists = !fresh;
        if (fresh) {
            auto s = std::make_unique<Stream>();
            s->name = name;
            s->pipe = !name.empty() && name[0] == '!';
            s->hasModifier = hasMod;
            s->hasBin = hasBin;
            s->modifier = mod;
            s->bin = bin;
            if (!s->name.empty() && !s->pipe && !o_.force && !o_.recover &&
                std::filesystem::exists(s->name))
                throw InputError("cannot open '" + s->name + "' for writing: File exists");
            streams_.push_back(std::move(s));
        }
        return it->second;
    };
    const bool picture = o_.outputFormat == 'c' && o_.xres > 0 && o_.yres > 0;
    for (const ContribModifier& m : o_.modifiers) {
        // RADIANCE compat (rcontrib.c addmodifier): with pictures, each modifier whose
        // spec takes a bin number starts past the bin files earlier modifiers made.
        int bin0 = 0;
        for (;; ++bin0) {
            bool exists = false;
            size_t s = streamFor(m.outSpec, m.name, bin0, exists);
            if (!(exists && picture && streams_[s]->hasBin)) break;
        }
        binNumber_.push_back(bin0);
        std::vector<size_t> bins;
        for (int j = 0; j < m.bins; ++j) {
            bool exists = false;
            size_t s = streamFor(m.outSpec, m.name, bin0 + j, exists);
            ++streams_[s]->reclen;
            bins.push_back(s);
        }
        streamOf_.push_back(std::move(bins));
    }
}

// RADIANCE 6 compat (rcontrib -fc -cs n): spectral samples make hyperspectral pictures.
const char* ContribOutput::format() const {
    return o_.outputFormat == 'c' && !sampling_.isRgb() ? kSpectralFormat
                                                        : formatName(o_.outputFormat);
}

// RADIANCE 6 compat: its hyperspectral pictures pad the resolution line (rtrace's too).
std::string ContribOutput::resolution() const {
    return resolutionLine(o_.xres, o_.yres, o_.outputFormat == 'c' && !sampling_.isRgb());
}

ContribOutput::~ContribOutput() {
    for (auto& s : streams_)
        if (s->file) s->pipe ? pclose(s->file) : std::fclose(s->file);
}

ContribOutput::Stream& ContribOutput::open(size_t index) {
    Stream& s = *streams_[index];
    if (s.opened) return s;
    s.opened = true;
    if (!s.name.empty() && !s.file) {
        s.file = s.pipe ? popen(s.name.c_str() + 1, "w") : std::fopen(s.name.c_str(), "wb");
        if (!s.file)
            throw InputError("cannot open '" + s.name + "' for writing: " + std::strerror(errno));
    }
    if (o_.header) {
        // RADIANCE compat (rc2.c getostream, printheader).
        std::string info;
        const int xr = o_.accumulate > 0 ? o_.xres : 0, yr = o_.accumulate > 0 ? o_.yres : 0;
        if (!s.name.empty()) {
            if (s.hasModifier || s.reclen == 1) info += "MODIFIER=" + s.modifier + "\n";
            if (s.hasBin) info += "BIN=" + std::to_string(s.bin) + "\n";
        }
        if (yr > 0) info += "NROWS=" + std::to_string(yr * (xr + (xr == 0))) + "\n";
        if (xr <= 0 || s.reclen > 1) info += "NCOLS=" + std::to_string(s.reclen) + "\n";
        std::string h = std::string(kHeaderMagic) + "\n";
        for (const std::string& l : sceneHeader_) h += l + "\n";
        std::vector<const char*> argv;
        for (const std::string& w : o_.commandWords) argv.push_back(w.c_str());
        h += commandLine(int(argv.size()), argv.data()) + "\n";
        h += "SOFTWARE= radphoton\n";
        h += captureTimeLines();  // RADIANCE compat (printheader)
        h += "NCOMP=" + std::to_string(sampling_.n) + "\n";
        if (!sampling_.isRgb())
            h += fmt::format("WAVELENGTH_SPLITS= {:g} {:g} {:g} {:g}\n", sampling_.wl[0],
                             sampling_.wl[1], sampling_.wl[2], sampling_.wl[3]);
        h += info;
        if (o_.outputFormat == 'f' || o_.outputFormat == 'd')
            h += std::endian::native == std::endian::big ? "BigEndian=1\n" : "BigEndian=0\n";
        h += std::string("FORMAT=") + format() + "\n\n";
        s.buffer += h;
    }
    if (s.reclen == 1 && o_.xres > 0 && o_.yres > 0) s.buffer += resolution();
    return s;
}

uint64_t ContribOutput::recover() {
    // RADIANCE compat (rc2.c recover_output): binary files only; the records every file
    // holds in full are kept, the rest is written again.
    if (o_.outputFormat == 'a') throw InputError("cannot recover ASCII output");
    const size_t recordBytes = valueSize(o_.outputFormat, size_t(sampling_.n));
    struct Found {
        size_t stream;
        uint64_t dataStart;
    };
    std::vector<Found> found;
    uint64_t records = UINT64_MAX;
    for (size_t i = 0; i < streams_.size(); ++i) {
        const Stream& s = *streams_[i];
        if (s.name.empty()) throw InputError("cannot recover from stdout");
        if (s.pipe) throw InputError("cannot recover from command");
        std::error_code ec;
        const uint64_t size = std::filesystem::file_size(s.name, ec);
        if (ec) {
            warn("missing recover file '" + s.name + "'");
            records = 0;
            break;
        }
        std::ifstream in(s.name, std::ios::binary);
        uint64_t start = 0;
        if (o_.header) {
            Header h;
            if (!tryReadHeader(in, h) || h.format() != format())
                throw InputError("format mismatch for '" + s.name + "'");
        }
        if (s.reclen == 1 && o_.xres > 0 && o_.yres > 0) {
            std::string line;
            if (!std::getline(in, line) || line + "\n" != resolution())
                throw InputError("resolution mismatch for '" + s.name + "'");
        }
        start = uint64_t(in.tellg());
        const uint64_t n = size > start ? (size - start) / (recordBytes * size_t(s.reclen)) : 0;
        records = std::min(records, n);
        found.push_back({i, start});
    }
    if (records == 0 || records == UINT64_MAX) {
        warn("no previous data to recover");
        return 0;
    }
    for (const Found& f : found) {
        Stream& s = *streams_[f.stream];
        const uint64_t keep = f.dataStart + records * recordBytes * size_t(s.reclen);
        std::filesystem::resize_file(s.name, keep);
        s.file = std::fopen(s.name.c_str(), "ab");
        if (!s.file)
            throw InputError("cannot open '" + s.name + "' for writing: " + std::strerror(errno));
        s.opened = true;  // the header is there already
    }
    return records;
}

std::vector<Color> ContribOutput::reload() {
    size_t bins = 0;
    for (const auto& m : streamOf_) bins += m.size();
    // In writeRecord's layout: each pass's bins in turn, a pass's bands as its colour.
    std::vector<Color> totals(bins * passes_.size());
    std::vector<std::unique_ptr<std::ifstream>> inputs(streams_.size());
    std::vector<bool> missing(streams_.size(), false);
    size_t k = 0;
    for (size_t m = 0; m < streamOf_.size(); ++m) {
        for (size_t j = 0; j < streamOf_[m].size(); ++j, ++k) {
            const size_t si = streamOf_[m][j];
            const Stream& s = *streams_[si];
            if (s.name.empty()) throw InputError("cannot reload from stdout");
            if (s.pipe) throw InputError("cannot reload from command");
            if (!inputs[si] && !missing[si]) {
                inputs[si] = std::make_unique<std::ifstream>(s.name, std::ios::binary);
                std::ifstream& in = *inputs[si];
                if (!in) {
                    warn("missing reload file '" + s.name + "'");
                    missing[si] = true;
                } else {
                    Header h;
                    if (o_.header && (!tryReadHeader(in, h) || h.format() != format()))
                        throw InputError("format mismatch for '" + s.name + "'");
                    std::string line;
                    if (s.reclen == 1 && o_.xres > 0 && o_.yres > 0 && !std::getline(in, line))
                        throw InputError("resolution mismatch for '" + s.name + "'");
                }
            }
            double v[spectral::kMaxSamples] = {};
            if (!missing[si] && !readValue(*inputs[si], v))
                throw InputError("missing data in '" + s.name + "'");
            for (size_t p = 0; p < passes_.size(); ++p)
                for (int c = 0; c < 3 && passes_[p].first + c < sampling_.n; ++c)
                    totals[p * bins + k][c] = v[passes_[p].first + c];
        }
    }
    return totals;
}

bool ContribOutput::readValue(std::istream& in, double* v) const {
    const size_t n = size_t(sampling_.n);
    switch (o_.outputFormat) {
        case 'a':
            for (size_t c = 0; c < n; ++c)
                if (!(in >> v[c])) return false;
            return true;
        case 'f': {
            float f[spectral::kMaxSamples];
            if (!in.read(reinterpret_cast<char*>(f), std::streamsize(n * sizeof(float))))
                return false;
            for (size_t c = 0; c < n; ++c) v[c] = f[c];
            return true;
        }
        case 'd':
            return bool(in.read(reinterpret_cast<char*>(v), std::streamsize(n * sizeof(double))));
        default: {
            if (n == 3) {
                Colr c;
                if (!in.read(reinterpret_cast<char*>(c.data()), 4)) return false;
                const auto rgb = colrToRgb(c);
                for (int i = 0; i < 3; ++i) v[i] = rgb[size_t(i)];
                return true;
            }
            uint8_t packed[spectral::kMaxSamples + 1];
            float f[spectral::kMaxSamples];
            if (!in.read(reinterpret_cast<char*>(packed), std::streamsize(n + 1))) return false;
            unpackSpectrum({packed, n + 1}, {f, n});
            for (size_t c = 0; c < n; ++c) v[c] = f[c];
            return true;
        }
    }
}

void ContribOutput::writeRecord(const std::vector<Color>& values, double scale, bool flush) {
    size_t bins = 0;
    for (const auto& m : streamOf_) bins += m.size();
    const std::vector<spectral::Pass>& passes = passes_;
    RP_CHECK(values.size() == bins * passes.size());
    size_t k = 0;
    double v[spectral::kMaxSamples];
    const size_t n = size_t(sampling_.n);
    for (size_t m = 0; m < streamOf_.size(); ++m) {
        for (size_t j = 0; j < streamOf_[m].size(); ++j, ++k) {
            Stream& s = open(streamOf_[m][j]);
            for (size_t p = 0; p < passes.size(); ++p)
                for (int c = 0; c < 3 && passes[p].first + c < sampling_.n; ++c)
                    v[passes[p].first + c] = values[p * bins + k][c] * scale;
            switch (o_.outputFormat) {
                case 'a':
                    for (size_t c = 0; c < n; ++c) {
                        char buf[32];
                        const int len = std::snprintf(buf, sizeof buf, "%.6e\t", v[c]);
                        s.buffer.append(buf, size_t(len));
                    }
                    break;
                case 'f':
                    for (size_t c = 0; c < n; ++c) {
                        const float f = float(v[c]);
                        s.buffer.append(reinterpret_cast<const char*>(&f), sizeof f);
                    }
                    break;
                case 'd':
                    s.buffer.append(reinterpret_cast<const char*>(v), n * sizeof(double));
                    break;
                default:
                    if (n == 3) {
                        const Colr c = toColr(v[0], v[1], v[2]);
                        s.buffer.append(reinterpret_cast<const char*>(c.data()), c.size());
                    } else {  // RADIANCE 6's common-exponent spectral pixels
                        float f[spectral::kMaxSamples];
                        uint8_t packed[spectral::kMaxSamples + 1];
                        for (size_t c = 0; c < n; ++c) f[c] = float(v[c]);
                        packSpectrum({f, n}, {packed, n + 1});
                        s.buffer.append(reinterpret_cast<const char*>(packed), n + 1);
                    }
            }
        }
    }
    for (auto& s : streams_) {
        if (!s->opened) continue;
        if (o_.outputFormat == 'a') s->buffer += '\n';
        // Small records collect until a block is worth writing, or a flush is due.
        if (flush || s->buffer.size() >= 1 << 16) s->write(stdout_);
        if (flush) {
            if (s->file)
                std::fflush(s->file);
            else if (s->name.empty())
                stdout_.flush();
        }
    }
}

void ContribOutput::close() {
    for (auto& s : streams_) {
        s->write(stdout_);
        if (!s->file) continue;
        int status = s->pipe ? pclose(s->file) : std::fclose(s->file);
        s->file = nullptr;
        if (status != 0) throw InputError("error closing output stream '" + s->name + "'");
    }
    stdout_.flush();
    if (!stdout_) throw InputError("write error on standard output");
}

}  // namespace rp::render
