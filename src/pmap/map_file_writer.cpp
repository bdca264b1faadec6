// Photon map files written by heap node (see map_file_writer.h).
#include "pmap/map_file_writer.h"

#include <filesystem>
#include <vector>

#include "pmap/photon_records.h"
#include "util/error.h"

namespace rp::pmap {

namespace {
// The file's name, checked before anything is created (PhotonMap::save's rules).
std::string checkedPath(const std::string& path, const PhotonMapFileInfo& info, bool overwrite) {
    const SourceLoc loc{path, 0};
    if (info.stats.numPhotons == 0) throw InputError(loc, "refusing to save an empty photon map");
    std::error_code ec;
    if (!overwrite && std::filesystem::exists(path, ec))
        throw InputError(loc, "photon map file exists; use -fo to overwrite it");
    return path;
}
}  // namespace

PhotonMapFileWriter::PhotonMapFileWriter(const std::string& path, const PhotonMapFileInfo& info,
                                         const std::string& commandLine, bool overwrite)
    : path_(checkedPath(path, info, overwrite)),
      overwrite_(overwrite),
      file_(path),
      numPhotons_(info.stats.numPhotons) {
    const std::string prologue = photonMapFilePrologue(info, commandLine);
    file_.write(prologue.data(), prologue.size());
    recordsAt_ = prologue.size();
}

void PhotonMapFileWriter::write(uint64_t first, std::span<const Photon> photons) {
    RP_CHECK(first >= 1 && first - 1 + photons.size() <= numPhotons_);
    std::vector<unsigned char> buf(photons.size() * kPhotonRecordSize);
    for (size_t i = 0; i < photons.size(); ++i)
        encodePhoton(buf.data() + i * kPhotonRecordSize, photons[i]);
    file_.writeAt(recordsAt_ + (first - 1) * kPhotonRecordSize, buf.data(), buf.size());
}

void PhotonMapFileWriter::commit() { file_.commit(overwrite_); }

}  // namespace rp::pmap
