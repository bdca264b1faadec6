// Weather inputs: .wea tapes as gendaymtx reads them, and EPW files as epw2wea converts
// them.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "gen/epw.h"
#include "gen/wea.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        std::istringstream in(text);
        (void)rp::gen::readWea(in, "fuzz.wea");
    } catch (const rp::InputError&) {
    }
    try {
        std::istringstream in(text);
        (void)rp::gen::epwToWea(in, "fuzz.epw");
    } catch (const rp::InputError&) {
    }
    return 0;
}
