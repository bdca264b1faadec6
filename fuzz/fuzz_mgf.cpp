// MGF geometry (pkgBSDF's MGF blocks, mgf2rad input), includes off.
#include <cstddef>
#include <cstdint>
#include <string>

#include "gen/mgf2rad.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        (void)rp::gen::mgfToRad(text, "fuzz.mgf", {});
    } catch (const rp::InputError&) {
    }
    return 0;
}
