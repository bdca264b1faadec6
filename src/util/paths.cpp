#include "util/paths.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace rp {

namespace {

// <prefix>/lib/radphoton when the running program is <prefix>/bin/<tool> (or
// <prefix>/libexec/radphoton/mpi/<tool>) and that folder exists; empty otherwise.
std::string installedLibDir() {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    for (const fs::path& prefix : {exe.parent_path().parent_path(),
                                   exe.parent_path().parent_path().parent_path().parent_path()}) {
        const fs::path lib = prefix / "lib" / "radphoton";
        if (fs::is_directory(lib, ec)) return lib.string();
    }
    return {};
}

}  // namespace

std::string projectLibDir() {
    if (const char* env = std::getenv("RADPHOTON_LIB"); env && *env) return env;
    // Found once: the executable does not move while it runs.
    static const std::string installed = installedLibDir();
    if (!installed.empty()) return installed;
#ifdef RP_LIB_DIR
    return RP_LIB_DIR;
#else
    return "lib";
#endif
}

}  // namespace rp
