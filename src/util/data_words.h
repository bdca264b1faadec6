// Words of RADIANCE's numeric data files (.dat data, .fnt fonts) as its fgetval reads
// them: whitespace separates words, and '#' starts a comment to the end of the line
// anywhere, even right after a number ("1.5#peak" is the word "1.5").
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rp {

struct DataWord {
    std::string text;
    int line = 0;  // 1-based line of the word
};

std::vector<DataWord> splitDataWords(std::string_view text);

}  // namespace rp
