// Error reporting shared by every module: where bad input came from (SourceLoc),
// the exception that carries it (InputError), and programmer-error checks (RP_CHECK).
// Printing and exit codes belong to each tool's main, never to src/.
#pragma once

#include <stdexcept>
#include <string>

namespace rp {

// A place in a user's input: file and 1-based line. line 0 means "whole file"
// (e.g. a missing file); an empty file means "no file" (command line, stdin).
struct SourceLoc {
    std::string file;
    int line = 0;

    // "office.rad:42", "office.rad", or "" when nothing is known.
    std::string str() const;
};

// Bad user input. what() is the complete one-line message: "file:line: message".
class InputError : public std::runtime_error {
public:
    InputError(const SourceLoc& loc, const std::string& message);
    explicit InputError(const std::string& message);

    const SourceLoc& loc() const { return loc_; }
    const std::string& message() const { return message_; }

private:
    SourceLoc loc_;
    std::string message_;
};

// A feature that a later release adds; still an InputError so tools report it cleanly.
InputError notSupportedYet(const SourceLoc& loc, const std::string& feature);

[[noreturn]] void checkFailed(const char* expr, const char* file, int line);

}  // namespace rp

// Programmer errors (violated invariants), distinct from bad input. Always on.
#define RP_CHECK(cond) ((cond) ? (void)0 : ::rp::checkFailed(#cond, __FILE__, __LINE__))
