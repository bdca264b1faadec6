// RADIANCE pictures (header, resolution line, flat and run-length RGBE/XYZE scanlines).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "image/picture.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        (void)rp::readPicture(in, "fuzz.hdr");
    } catch (const rp::InputError&) {
    }
    return 0;
}
