// .dat data files (RADIANCE's data.c format, used by brightdata, colordata, texdata,
// mixdata and luminaire distributions): parsing, then interpolation at a few points
// inside and outside the axes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "calc/data_file.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const rp::calc::DataFile f = rp::calc::DataFile::parse(text, "fuzz.dat");
        std::vector<double> p(size_t(f.dimensions()));
        for (double x : {-1e9, -1.0, 0.0, 0.5, 3.0, 1e9}) {
            for (double& c : p) c = x;
            (void)f.value(p);
        }
    } catch (const rp::InputError&) {
    }
    return 0;
}
