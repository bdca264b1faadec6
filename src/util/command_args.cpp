// @file and $EVAR expansion (see command_args.h).
#include "util/command_args.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "util/error.h"

namespace rp {

std::vector<std::string> splitWords(const std::string& text) {
    std::vector<std::string> words;
    size_t i = 0;
    const size_t n = text.size();
    while (i < n) {
        while (i < n && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i >= n) break;
        std::string w;
        // A word runs to the next unquoted white space; quoted parts keep their spaces.
        while (i < n && !std::isspace(static_cast<unsigned char>(text[i]))) {
            char c = text[i];
            if (c == '"' || c == '\'') {
                size_t close = text.find(c, i + 1);
                if (close == std::string::npos) close = n;
                w.append(text, i + 1, close - i - 1);
                i = close < n ? close + 1 : n;
            } else {
                w += c;
                ++i;
            }
        }
        words.push_back(std::move(w));
    }
    return words;
}

void expandArgAt(std::vector<std::string>& args, size_t i) {
    for (int depth = 0;
         i < args.size() && !args[i].empty() && (args[i][0] == '@' || args[i][0] == '$'); ++depth) {
        const std::string arg = args[i];
        if (depth >= 64) throw InputError("cannot expand '" + arg + "' (nested too deeply)");
        std::string text;
        if (arg[0] == '@') {
            std::ifstream in(arg.substr(1), std::ios::binary);
            if (!in) throw InputError("cannot expand '" + arg + "'");
            text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        } else {
            const char* v = std::getenv(arg.c_str() + 1);
            if (v == nullptr) throw InputError("cannot expand '" + arg + "'");
            text = v;
        }
        std::vector<std::string> words = splitWords(text);
        args.erase(args.begin() + static_cast<std::ptrdiff_t>(i));
        args.insert(args.begin() + static_cast<std::ptrdiff_t>(i), words.begin(), words.end());
    }
}

std::vector<std::string> argVector(int argc, const char* const* argv) {
    return std::vector<std::string>(argv, argv + argc);
}

}  // namespace rp
