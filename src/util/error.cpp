#include "util/error.h"

#include <cstdio>
#include <cstdlib>

namespace rp {

std::string SourceLoc::str() const {
    if (file.empty()) return line > 0 ? "line " + std::to_string(line) : std::string();
    if (line <= 0) return file;
    return file + ":" + std::to_string(line);
}

static std::string compose(const SourceLoc& loc, const std::string& message) {
    std::string where = loc.str();
    return where.empty() ? message : where + ": " + message;
}

InputError::InputError(const SourceLoc& loc, const std::string& message)
    : std::runtime_error(compose(loc, message)), loc_(loc), message_(message) {}

InputError::InputError(const std::string& message)
    : std::runtime_error(message), message_(message) {}

InputError notSupportedYet(const SourceLoc& loc, const std::string& feature) {
    return InputError(loc, "not supported yet: " + feature);
}

void checkFailed(const char* expr, const char* file, int line) {
    std::fprintf(stderr, "internal error: check '%s' failed at %s:%d\n", expr, file, line);
    std::abort();
}

}  // namespace rp
