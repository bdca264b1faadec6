// RADIANCE's argument expansion for every tool's options (expandarg in common/expandarg.c):
// an option-position argument "@file" is replaced by the words of that file and "$EVAR" by
// the words of that environment variable. Option parsing itself lives in util/options.h.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rp {

// Splits text into words at white space; a word may be quoted with '...' or "..." to hold
// white space (the quotes are removed), as RADIANCE's wordstring does for @files.
std::vector<std::string> splitWords(const std::string& text);

// Expands args[i] in place while it begins with '@' or '$' (the expansion may itself start
// with one), so that args[i] is afterwards an ordinary argument or past the end. Callers run
// it at each option position only, as RADIANCE does: option values are never expanded.
// Throws InputError "cannot expand '<arg>'" for an unreadable file or an unset variable,
// and for expansions nested deeper than 64 (a file that names itself).
void expandArgAt(std::vector<std::string>& args, size_t i);

// argv as strings (argv[0] included).
std::vector<std::string> argVector(int argc, const char* const* argv);

}  // namespace rp
