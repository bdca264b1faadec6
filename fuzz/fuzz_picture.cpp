// RADIANCE pictures (header, resolution line, flat and run-length RGBE/XYZE scanlines), and
// RADIANCE 6's spectral pictures (NCOMP=, WAVELENGTH_SPLITS=, common-exponent samples)
// through both readers.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "image/picture.h"
#include "image/spectral_picture.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        std::istringstream in(bytes);
        (void)rp::readPicture(in, "fuzz.hdr");
    } catch (const rp::InputError&) {
    }
    try {
        std::istringstream in(bytes);
        (void)rp::readSpectralPicture(in, "fuzz.hsr");
    } catch (const rp::InputError&) {
    }
    try {
        std::istringstream in(bytes);
        (void)rp::readPictureAsRgb(in, "fuzz.hsr", rp::SpectralToRgb::kBandAverages);
    } catch (const rp::InputError&) {
    }
    return 0;
}
