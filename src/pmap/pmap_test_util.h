// Helpers shared by the pmap tests that read, corrupt and reload map files.
#pragma once

#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "util/error.h"

namespace rp::pmap::test {

// The bytes of the file at `path` ("" if it cannot be read).
inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The message of the InputError that f throws, or "(no InputError)".
inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

}  // namespace rp::pmap::test
