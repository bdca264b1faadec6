#include "util/data_words.h"

#include <cctype>

namespace rp {

std::vector<DataWord> splitDataWords(std::string_view text) {
    std::vector<DataWord> out;
    int line = 1;
    size_t i = 0;
    while (i < text.size()) {
        char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
        } else if (c == '#') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else {
            size_t start = i;
            while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) &&
                   text[i] != '#')
                ++i;
            out.push_back({std::string(text.substr(start, i - start)), line});
        }
    }
    return out;
}

}  // namespace rp
