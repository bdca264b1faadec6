// rcalc's record formats (-i/-o): the first line is a format, the rest input records
// matched against it.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "calc/record_format.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::size_t nl = text.find('\n');
    const std::string spec = text.substr(0, nl);
    std::istringstream in(nl == std::string::npos ? std::string() : text.substr(nl + 1));
    std::ostringstream passive;
    try {
        for (bool ignoreEol : {false, true}) {
            std::vector<rp::calc::StringVar> strings;
            rp::calc::RecordReader reader(rp::calc::parseRecordFormat(spec, ignoreEol), !ignoreEol,
                                          ignoreEol, ignoreEol, strings);
            in.clear();
            in.seekg(0);
            reader.begin(in, passive);
            for (int n = 0; n < 1000 && reader.next(); ++n) {
            }
        }
    } catch (const rp::InputError&) {
    }
    return 0;
}
