// Photon map files written by heap node (see map_file_writer.h).
#include "pmap/map_file_writer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "pmap/photon_records.h"
#include "pmap/record_checksums.h"
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
    PhotonMapFileInfo withChecksums = info;
    withChecksums.checksumBlock = kChecksumBlock;
    const std::string prologue = photonMapFilePrologue(withChecksums, commandLine);
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

void PhotonMapFileWriter::commit() {
    // The records were written in any order: their checksums are taken from the file,
    // block by block, once all are there (from the page cache, as a rule).
    // Blocks in parallel (in the caller's task arena, as the writes).
    RecordChecksums sums;
    sums.block = kChecksumBlock;
    sums.crc.resize(checksumBlocks(numPhotons_, kChecksumBlock));
    tbb::parallel_for(size_t(0), sums.crc.size(), [&](size_t b) {
        const uint64_t first = uint64_t(b) * kChecksumBlock;
        const size_t n = size_t(std::min<uint64_t>(kChecksumBlock, numPhotons_ - first));
        std::vector<unsigned char> raw(n * kPhotonRecordSize);
        file_.readAt(recordsAt_ + first * kPhotonRecordSize, raw.data(), raw.size());
        sums.crc[b] = recordsChecksum(raw.data(), raw.size());
    });
    const std::string trailer = sums.encode();
    file_.writeAt(recordsAt_ + numPhotons_ * kPhotonRecordSize, trailer.data(), trailer.size());
    file_.commit(overwrite_);
}

}  // namespace rp::pmap
