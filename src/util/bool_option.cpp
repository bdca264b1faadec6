// RADIANCE check_bool (see bool_option.h).
#include "util/bool_option.h"

#include "util/error.h"

namespace rp {

bool boolSuffix(const std::string& opt, size_t len, bool current) {
    if (opt.size() == len) return !current;
    if (opt.size() == len + 1) {
        switch (opt[len]) {
            case '+':
            case 'y':
            case 'Y':
            case 't':
            case 'T':
            case '1':
                return true;
            case '-':
            case 'n':
            case 'N':
            case 'f':
            case 'F':
            case '0':
                return false;
            default:
                break;
        }
    }
    throw InputError("unknown option '" + opt + "'");
}

}  // namespace rp
