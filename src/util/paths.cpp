#include "util/paths.h"

#include <cstdlib>

namespace rp {

std::string projectLibDir() {
    if (const char* env = std::getenv("RADPHOTON_LIB"); env && *env) return env;
#ifdef RP_LIB_DIR
    return RP_LIB_DIR;
#else
    return "lib";
#endif
}

}  // namespace rp
