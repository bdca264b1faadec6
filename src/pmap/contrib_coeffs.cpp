// Coefficient files of precomputed contribution maps (contrib_coeffs.h).
#include "pmap/contrib_coeffs.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/error.h"
#include "util/file_write.h"
#include "util/header.h"
#include "util/options.h"

namespace rp::pmap {

std::string coeffFolder(const std::string& mapFile) { return mapFile + ".rc"; }

std::string coeffFile(const std::string& mapFile, const std::string& modifier) {
    std::string name = modifier;
    for (char& c : name)
        if (c == '/' || c == '\0') c = '_';
    if (name == "." || name == "..") name = "_" + name;
    return coeffFolder(mapFile) + "/" + name + ".rc";
}

std::string optionFile(const std::string& mapFile) { return mapFile + ".opt"; }

namespace {

std::string codecText(const CoeffCodec& c) {
    return c.raw() ? "raw" : "D4 " + std::to_string(c.length()) + " " + std::to_string(c.kept());
}

// A word for an option file, quoted as RADIANCE's fputword does when it holds white space.
std::string optionWord(const std::string& w) {
    if (w.find_first_of(" \t\n") == std::string::npos && !w.empty()) return w;
    return w.find('"') == std::string::npos ? '"' + w + '"' : '\'' + w + '\'';
}

}  // namespace

// ---- writing ----

struct CoeffWriter::Impl {
    std::string path;
    AtomicFile file;
    uint64_t dataOffset = 0;
    explicit Impl(const std::string& p) : path(p), file(p) {}
};

CoeffWriter::CoeffWriter(const std::string& path, const CoeffInfo& info,
                         const std::string& commandLine)
    : codec_(info.bins, info.compression) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    if (ec) throw InputError(SourceLoc{path, 0}, "cannot make folder: " + ec.message());
    impl_ = std::make_unique<Impl>(path);
    Header h;
    if (!commandLine.empty()) h.lines.push_back(commandLine);
    h.lines.push_back("MODIFIER=" + info.modifier);
    h.lines.push_back("NBINS=" + std::to_string(info.bins));
    h.lines.push_back("CONTRIBUTIONS=" + std::to_string(info.contributions ? 1 : 0));
    h.lines.push_back("CODEC=" + codecText(codec_));
    h.lines.push_back("NRECORDS=" + std::to_string(info.records));
    h.lines.push_back(std::string("FORMAT=") + kCoeffFormat);
    std::ostringstream text;
    writeHeader(text, h);
    const std::string s = text.str();
    impl_->file.write(s.data(), s.size());
    impl_->dataOffset = s.size();
}

CoeffWriter::~CoeffWriter() = default;

void CoeffWriter::write(uint64_t i, const uint8_t* record) {
    const size_t n = codec_.recordBytes();
    impl_->file.writeAt(impl_->dataOffset + i * n, record, n);
}

void CoeffWriter::commit(bool overwrite) { impl_->file.commit(overwrite); }

// ---- reading ----

namespace {

CoeffInfo parseInfo(const Header& h, const SourceLoc& loc, std::string& codec) {
    if (h.format() != kCoeffFormat)
        throw InputError(loc, "not a precomputed contribution file (FORMAT=" + h.format() + ")");
    CoeffInfo info;
    info.modifier = h.value("MODIFIER");
    const auto bins = parseReal(h.value("NBINS"));
    const auto records = parseReal(h.value("NRECORDS"));
    const auto contrib = parseReal(h.value("CONTRIBUTIONS"));
    if (info.modifier.empty() || !bins || *bins < 1 || *bins > 65536 || !records || *records < 0 ||
        !contrib)
        throw InputError(loc, "bad precomputed contribution header");
    info.bins = int(*bins);
    info.records = uint64_t(*records);
    info.contributions = *contrib != 0;
    codec = h.value("CODEC");
    return info;
}

// The codec a CODEC= line names (the compression it was made with is implied).
CoeffCodec parseCodec(const std::string& text, int bins, const SourceLoc& loc) {
    if (text == "raw") return CoeffCodec(bins, 0);
    std::istringstream in(text);
    std::string name;
    int length = 0, kept = 0;
    in >> name >> length >> kept;
    CoeffCodec probe(bins, 0.5);
    if (name != "D4" || !in || length != probe.length() || kept > length)
        throw InputError(loc, "bad precomputed contribution codec '" + text + "'");
    // The compression that gives `kept` back (wavelet.h: the approximation and a share of
    // the details); all kept is still a transform, not raw bins.
    const int a = probe.approximation();
    if (kept < a) throw InputError(loc, "bad precomputed contribution codec '" + text + "'");
    const double comp = length > a ? 1 - double(kept - a) / (length - a) : 0;
    return CoeffCodec(bins, std::max(comp, 1e-12));
}

}  // namespace

CoeffFile::CoeffFile(const std::string& path) : path_(path) {
    const SourceLoc loc{path, 0};
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(loc, std::string("cannot open: ") + std::strerror(errno));
    const Header h = readHeader(in, path);
    std::string codec;
    info_ = parseInfo(h, loc, codec);
    codec_ = parseCodec(codec, info_.bins, loc);
    const int a = codec_.approximation();
    info_.compression = codec_.raw() || codec_.length() == a
                            ? 0
                            : 1 - double(codec_.kept() - a) / (codec_.length() - a);
    const std::streamoff at = in.tellg();
    if (at < 0) throw InputError(loc, "cannot read precomputed contributions");
    dataOffset_ = size_t(at);
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat st {};
    if (fd < 0 || ::fstat(fd, &st) != 0) {
        if (fd >= 0) ::close(fd);
        throw InputError(loc, std::string("cannot open: ") + std::strerror(errno));
    }
    const uint64_t need = dataOffset_ + info_.records * codec_.recordBytes();
    if (uint64_t(st.st_size) < need) {
        ::close(fd);
        throw InputError(loc, "truncated precomputed contributions (" + std::to_string(st.st_size) +
                                  " bytes, expected " + std::to_string(need) + ")");
    }
    mapped_ = size_t(st.st_size);
    void* p = mapped_ ? ::mmap(nullptr, mapped_, PROT_READ, MAP_SHARED, fd, 0) : nullptr;
    ::close(fd);
    if (p == MAP_FAILED) throw InputError(loc, std::string("cannot map: ") + std::strerror(errno));
    base_ = static_cast<const uint8_t*>(p);
}

CoeffFile::CoeffFile(CoeffFile&& o) noexcept
    : path_(std::move(o.path_)),
      info_(std::move(o.info_)),
      codec_(o.codec_),
      base_(o.base_),
      mapped_(o.mapped_),
      dataOffset_(o.dataOffset_) {
    o.base_ = nullptr;
    o.mapped_ = 0;
}

CoeffFile::~CoeffFile() {
    if (base_) ::munmap(const_cast<uint8_t*>(base_), mapped_);
}

bool CoeffFile::decode(uint64_t i, std::span<Rgb> out, CoeffCodec::Scratch& s) const {
    if (i >= info_.records) return false;
    codec_.decode(base_ + dataOffset_ + i * codec_.recordBytes(), out, s);
    return true;
}

std::string rcontribOptionText(const std::vector<ContribModifier>& modifiers,
                               const std::vector<CalcDefinition>& definitions, bool contributions) {
    std::string out = contributions ? "-V+\n" : "-V-\n";
    for (const CalcDefinition& d : definitions)
        out += (d.file ? "-f " : "-e ") + optionWord(d.text) + "\n";
    std::string params;  // rcontrib keeps a -p for every -m after it
    for (const ContribModifier& m : modifiers) {
        if (m.params != params) out += "-p " + optionWord(m.params) + " ";
        params = m.params;
        out += "-b " + optionWord(m.binExpr) + " -bn " + std::to_string(m.bins) + " -m " +
               optionWord(m.name) + "\n";
    }
    return out;
}

}  // namespace rp::pmap
