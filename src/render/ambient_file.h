// The -af ambient file: irradiance cache records kept across runs. A RADIANCE header
// (FORMAT=radphoton_ambient, the -a options that made the records, the record size)
// followed by fixed-size little-endian binary records appended by each run, as RADIANCE
// appends to its own ambient files. Not RADIANCE's own binary AMBVAL layout.
#pragma once

#include <string>
#include <vector>

#include "render/irradiance_cache.h"
#include "render/render_options.h"

namespace rp::render {

constexpr const char* kAmbientFormat = "radphoton_ambient";
constexpr size_t kAmbientRecordBytes = 88;
// Files written before records kept their corral (AmbientRecord::corral) are read, and
// appended to, in their own 84-byte records; their records are not tested for leaks.
constexpr size_t kLegacyAmbientRecordBytes = 84;

// "-aa 0.1 -ar 256 -ad 1024 -as 512 -ab 2": the options that decide what records mean,
// as stored in the header (AMBIENT_OPTIONS=).
std::string ambientFileOptions(const AmbientOptions& o);

struct AmbientFileContents {
    std::string options;                 // the AMBIENT_OPTIONS= line ("" if absent)
    std::string bands;                   // BANDS=: a spectral pass's (spectral::passLabel)
    std::vector<AmbientRecord> records;  // in file order
};

// Reads a whole ambient file. Throws InputError naming `path` for an unreadable file,
// another format, a different record size, a partial record at the end or a record with
// non-finite or impossible values.
AmbientFileContents readAmbientFile(const std::string& path);
// "ambient file of <bands>, not of this run's <bands>" (RGB for none).
std::string bandsProblem(const std::string& file, const std::string& run);

// Adds `records` at the end of `path`. A missing file is created with a header holding
// `options` and `bands` (written to a temporary file and renamed, so a crash leaves no
// half header); an existing one is first checked to be an ambient file of those bands
// (InputError otherwise).
void appendAmbientFile(const std::string& path, const std::string& options,
                       const std::vector<AmbientRecord>& records, const std::string& bands = "");

// The fixed binary layout, exposed for tests: position 3 x f64, normal 3 x f32, value
// 3 x f32, radius f32, gradPosition 3 x f32, gradDirection 3 x f32, weight f32, level i32,
// corral u32 (not in the legacy 84-byte records).
void encodeAmbientRecord(const AmbientRecord& r, unsigned char* out,
                         size_t bytes = kAmbientRecordBytes);
AmbientRecord decodeAmbientRecord(const unsigned char* in, size_t bytes = kAmbientRecordBytes);

}  // namespace rp::render
