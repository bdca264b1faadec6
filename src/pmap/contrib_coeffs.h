// The files of a precomputed contribution photon map (mkpmap -apC file n bwidth comp with
// -m/-M; precomp_contrib.h), our layout where the development branch leaves it open:
//   file           the precomputed photons, a photon map of type PreCompContrib whose
//                  photons' `primary` is the index of their records;
//   file.rc/M.rc   one per modifier M: a RADIANCE-style header (MODIFIER=, NBINS=,
//                  CONTRIBUTIONS=, CODEC=, NRECORDS=, FORMAT=) and fixed-size records in
//                  photon index order (wavelet.h), read through a memory map so that the
//                  system pages them in as lookups need them (maps larger than memory);
//   file.opt       the options that give rcontrib the same bins (rcontrib @file.opt).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "pmap/contrib_bins.h"
#include "pmap/wavelet.h"

namespace rp::pmap {

constexpr const char* kCoeffFormat = "Radiance_PreCompContrib_Coefficients";

std::string coeffFolder(const std::string& mapFile);  // mapFile + ".rc"
// The modifier's file in coeffFolder; characters a file name cannot hold become '_'.
std::string coeffFile(const std::string& mapFile, const std::string& modifier);
std::string optionFile(const std::string& mapFile);  // mapFile + ".opt"

// What a coefficient file says of its records.
struct CoeffInfo {
    std::string modifier;
    int bins = 1;
    double compression = 0;
    bool contributions = false;  // -V+: flux; -V-: per unit radiance of each source
    uint64_t records = 0;
};

// The header and records (`records` = info.records x codec.recordBytes() bytes) as one
// file, written completely or not at all (InputError naming it on failure).
class CoeffWriter {
public:
    CoeffWriter(const std::string& path, const CoeffInfo& info, const std::string& commandLine);
    ~CoeffWriter();
    const CoeffCodec& codec() const { return codec_; }
    // Record i (any order, from any thread).
    void write(uint64_t i, const uint8_t* record);
    void commit(bool overwrite);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    CoeffCodec codec_;
};

// A coefficient file opened for lookups (memory-mapped).
class CoeffFile {
public:
    // Throws InputError naming `path`: missing, not a coefficient file, bad header
    // values, or fewer bytes than NRECORDS records.
    explicit CoeffFile(const std::string& path);
    ~CoeffFile();
    CoeffFile(CoeffFile&& o) noexcept;
    CoeffFile(const CoeffFile&) = delete;
    CoeffFile& operator=(const CoeffFile&) = delete;

    const CoeffInfo& info() const { return info_; }
    const std::string& path() const { return path_; }
    // The bins of record i into `out` (info().bins entries); false past the last record.
    bool decode(uint64_t i, std::span<Rgb> out, CoeffCodec::Scratch& s) const;

private:
    std::string path_;
    CoeffInfo info_;
    CoeffCodec codec_{1, 0};
    const uint8_t* base_ = nullptr;
    size_t mapped_ = 0;
    size_t dataOffset_ = 0;
};

// The text of file.opt: -V, the -e/-f definitions in order, then -p, -b, -bn before each
// -m as mkpmap was given them, quoted where a word holds white space.
std::string rcontribOptionText(const std::vector<ContribModifier>& modifiers,
                               const std::vector<CalcDefinition>& definitions, bool contributions);

}  // namespace rp::pmap
