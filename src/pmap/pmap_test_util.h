// Helpers shared by the pmap tests that read, corrupt and reload map files.
#pragma once

#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "util/error.h"

namespace rp::pmap::test {

// The bytes of the file at `path` ("" if it cannot be read).
inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The bytes of a map file saved by radphoton as RADIANCE writes the same map: without the
// RP_CRC32 header line and the checksums after its `n` records (record_checksums.h).
inline std::string withoutChecksums(std::string data, uint64_t n) {
    const size_t line = data.find("RP_CRC32=");
    if (line == std::string::npos) return data;
    data.erase(line, data.find('\n', line) + 1 - line);
    data.resize(data.size() - 4 * ((n + 4095) / 4096));
    return data;
}

// The message of the InputError that f throws, or "(no InputError)".
inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

}  // namespace rp::pmap::test
