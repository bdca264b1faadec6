// genssky's inputs: its aerosol table (a RADIANCE data file over altitude and band, turned
// into the atmosphere's model), or, when the first byte is 0xff, its cached atmosphere
// tables (atmos_data/*.atm: a valid header and key, then the other bytes, read back for a
// small resolution). Errors must be InputError or a refused cache, never a crash.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "calc/data_file.h"
#include "gen/atmosphere.h"
#include "util/error.h"

namespace {

rp::gen::atmos::Resolution small() {
    rp::gen::atmos::Resolution r;
    r.transmittanceR = 4;
    r.transmittanceMu = 4;
    r.scatteringR = 2;
    r.scatteringMu = 4;
    r.scatteringMuS = 2;
    r.scatteringNu = 2;
    r.irradianceR = 2;
    r.irradianceMuS = 2;
    r.orders = 2;
    return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    using namespace rp::gen::atmos;
    if (data[0] != 0xff) {
        try {
            const std::string text(reinterpret_cast<const char*>(data), size);
            const rp::calc::DataFile f = rp::calc::DataFile::parse(text, "fuzz_mie.dat");
            const Model m = Model::make(RayleighProfile::Tropical, f, 1.0, 0.2);
            (void)m.mieAt(-10);
            (void)m.mieAt(30000);
            (void)m.mieAt(1e9);
        } catch (const rp::InputError&) {
        }
        return 0;
    }
    const std::string body(reinterpret_cast<const char*>(data) + 1, size - 1);
    static const std::string path = "/tmp/fuzz_atmos_" + std::to_string(getpid()) + ".atm";
    const std::string key = "fuzz key";
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        const uint32_t n = uint32_t(key.size());
        out.write("RPATMOS1", 8);
        out.write(reinterpret_cast<const char*>(&n), sizeof n);
        out << key << body;
    }
    Model m;
    m.mie.assign(2, Spectrum{});
    Atmosphere a;
    if (a.load(path, m, small(), key)) (void)a.radiance({0, 0, 1}, {0, 0.6, 0.8}, 10);
    std::remove(path.c_str());
    return 0;
}
