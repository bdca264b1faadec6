// Test helper (no library code): RADIANCE generator outputs stored under
// tests/data/gen_radiance, each starting with its "# prog args" line, which is also the
// command that made it; and a 64-bit FNV-1a hash for outputs too big to store.
#pragma once

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace rp::gen::testing {

struct ReferenceOutput {
    std::vector<std::string> args;  // from the header line, args[0] = program name
    std::string text;               // the whole file
};

inline ReferenceOutput readReferenceOutput(const std::string& file) {
    std::ifstream in(std::string(RP_SOURCE_DIR) + "/tests/data/gen_radiance/" + file,
                     std::ios::binary);
    ReferenceOutput ref;
    std::ostringstream all;
    all << in.rdbuf();
    ref.text = all.str();
    std::istringstream header(ref.text.substr(0, ref.text.find('\n')));
    std::string word;
    header >> word;  // "#"
    while (header >> word) ref.args.push_back(word);
    return ref;
}

inline uint64_t fnv1a64(std::string_view s) {
    uint64_t h = 0xcbf29ce484222325ULL;
    for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
    return h;
}

}  // namespace rp::gen::testing
