// radcompare's readers: the input split at its first NUL into a reference and a test
// file, compared as their headers say (pictures, text, float/double data, bytes).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "image/radcompare.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::size_t cut = text.find('\0');
    const std::string a = text.substr(0, cut);
    const std::string b = cut == std::string::npos ? a : text.substr(cut + 1);
    std::ostringstream out;
    rp::RadcompareOptions opt;
    opt.report = rp::CompareReport::kVerbose;
    try {
        (void)rp::compareRadianceData(opt, "a", a, "b", b, out);
    } catch (const rp::InputError&) {
    }
    return 0;
}
