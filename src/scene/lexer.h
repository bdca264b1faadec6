// Character-level reading of RADIANCE scene text: words (optionally quoted), comments,
// "!command" lines with backslash continuation, line numbers, and the number syntax
// RADIANCE accepts for integer and real arguments. Knows nothing about primitive types.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rp {

// Integer as RADIANCE's isint() accepts it: optional sign, decimal digits.
bool parseInteger(std::string_view word, long& out);
// Real as RADIANCE's isflt() accepts it: optional sign, digits with an optional point
// (at least one digit on either side), optional exponent: 1 -1. .5 +2e-3 1E+2.
bool parseReal(std::string_view word, double& out);

class SceneLexer {
public:
    explicit SceneLexer(std::string_view text) : text_(text) {}

    // Skips white space (counting lines); true if anything remains.
    bool skipSpace();
    char peek() const { return text_[pos_]; }
    int line() const { return line_; }

    // Skips a '#' comment through the end of its line.
    void skipComment();
    // Reads a '!' command line (the '!' itself excluded), joining backslash-newline
    // continuations as the shell would. Returns the command text.
    std::string readCommand();
    // Reads the next word: a run of non-white characters, or text between matching
    // double or single quotes (RADIANCE's fgetword). False at end of text, or for an
    // unterminated quote. `line` receives the line the word starts on.
    bool readWord(std::string& word, int& line);

private:
    std::string_view text_;
    size_t pos_ = 0;
    int line_ = 1;
};

}  // namespace rp
