// What a tool's main says about an exception that reached it: one line and an exit code,
// whatever the exception (DEVELOPERS: tools catch every exception at main).
#pragma once

#include <exception>
#include <functional>
#include <iostream>
#include <new>
#include <string>

#include "util/error.h"
#include "util/warnings.h"

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

// The main of a filter that writes standard output (the matrix tools): its warnings as
// "name: warning - ..." after what it wrote so far, standard output flushed and checked
// (`writeError` when it fails), and any exception as "name: ..." with its exit code.
inline int runFilter(const char* name, const char* writeError, const std::function<void()>& body) {
    try {
        std::ios::sync_with_stdio(false);
        setWarningSink([name](const std::string& m) {
            std::cout.flush();
            std::cerr << name << ": warning - " << m << '\n';
        });
        body();
        std::cout.flush();
        if (!std::cout) throw InputError(writeError);
        return 0;
    } catch (...) {
        std::cout.flush();
        const MainError e = currentMainError();
        std::cerr << name << ": " << e.line << '\n';
        return e.exitCode;
    }
}

}  // namespace rp::tools
