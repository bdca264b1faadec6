// What a tool's main says about an exception that reached it: one line and an exit code,
// whatever the exception (DEVELOPERS: tools catch every exception at main).
#pragma once

#include <exception>
#include <new>
#include <string>

#include "util/error.h"

namespace rp::tools {

struct MainError {
    std::string line;  // without the "program: " prefix
    int exitCode = 1;
};

// Bad input as it says (exit 1); running out of memory, which an option or a file can ask
// for (rtrace -ad 2000000000), as such (exit 1); anything else as an internal error
// (exit 2). Call inside a catch block.
inline MainError currentMainError() {
    try {
        throw;
    } catch (const InputError& e) {
        return {e.what(), 1};
    } catch (const std::bad_alloc&) {
        return {"out of memory (an option or input asks for more than this machine has)", 1};
    } catch (const std::exception& e) {
        return {std::string("internal error: ") + e.what(), 2};
    } catch (...) {
        return {"internal error", 2};
    }
}

}  // namespace rp::tools
