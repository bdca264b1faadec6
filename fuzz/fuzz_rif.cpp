// rad input files: RIF lines (continuations, escapes, comments), the variables' checks,
// the listing, and what rad derives from them (rendering options, views, pfilt).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "rad/rad_settings.h"
#include "rad/rif.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        rp::rad::RifVars v;
        v.load(in, "fuzz.rif");
        v.check(false);
        (void)v.listing();
        v.setDefault(rp::rad::Var::kZone, "I 0 1 0 1 0 1");
        for (rp::rad::Var q :
             {rp::rad::Var::kQuality, rp::rad::Var::kDetail, rp::rad::Var::kVariability})
            v.setDefault(q, "M");
        v.setDefault(rp::rad::Var::kPenumbras, "F");
        v.setDefault(rp::rad::Var::kIndirect, "0");
        rp::rad::Programs p;
        (void)rp::rad::renderSettings(v, 1.5, false, p);
        (void)rp::rad::pfiltOptions(v, p);
        std::string name;
        for (int n = 0; n < 8 && rp::rad::selectView(v, nullptr, n, &name); ++n) {
        }
    } catch (const rp::InputError&) {
    }
    return 0;
}
