// rtrace's ray input in each -f input format: the first byte picks ASCII, float or
// double records, the rest is the input. Bad records must be InputErrors or Bad status,
// never a crash or a hang.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "render/rtrace_io.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    static const char kFormats[3] = {'a', 'f', 'd'};
    const char format = kFormats[data[0] % 3];
    std::istringstream in(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
    try {
        rp::render::RayReader reader(in, format);
        rp::render::InputRay ray;
        while (reader.next(ray) == rp::render::RayReader::Status::Ok) {
        }
    } catch (const rp::InputError&) {
    }
    return 0;
}
