// mkillum's variables and their comment lines (see illum_settings.h).
#include "illum/illum_settings.h"

#include <cctype>
#include <vector>

#include "scene/lexer.h"
#include "util/options.h"

namespace rp::illum {

namespace {

constexpr std::string_view kKeyword = "#@mkillum";

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::vector<std::string_view> splitWords(std::string_view s) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && isSpace(s[i])) ++i;
        size_t start = i;
        while (i < s.size() && !isSpace(s[i])) ++i;
        if (i > start) words.push_back(s.substr(start, i - start));
    }
    return words;
}

// One word of an option line; `value` is what follows "x=" (empty if none).
struct Word {
    std::string_view text;
    std::string_view value;
    bool assigns = false;  // the second character is '='
};

[[noreturn]] void badWord(const SourceLoc& loc, const Word& w, const std::string& why) {
    throw InputError(loc, "bad #@mkillum option '" + std::string(w.text) + "': " + why);
}

int countValue(const SourceLoc& loc, const Word& w, const char* what) {
    long v = 0;
    if (!rp::parseInteger(w.value, v)) badWord(loc, w, std::string("expected ") + what);
    if (v < 0 || v > 100'000'000) badWord(loc, w, "must be between 0 and 100000000");
    return int(v);
}

// The variables that take a value: m f i e c d s b o.
void applyValue(const SourceLoc& loc, const Word& w, IllumSettings& s, OptionLine& result) {
    const std::string value(w.value);
    switch (w.text[0]) {
        case 'm':
            if (value.empty()) badWord(loc, w, "expected a material name");
            s.material = value;
            if (!s.clobber) {
                s.dataFile = value;
                s.dataFileNumber = 0;
            }
            return;
        case 'f':
            // "f=" alone: data files named after the material again, never clobbered.
            s.dataFile = value.empty() ? s.material : value;
            s.dataFileNumber = 0;
            s.clobber = !value.empty();
            return;
        case 'i':
        case 'e':
            if (value.empty()) badWord(loc, w, "expected a modifier name");
            s.selection = w.text[0] == 'i' ? Selection::kOnly : Selection::kAllBut;
            s.selectModifier = value;
            return;
        case 'c':
            if (value.empty() || (value[0] != 'a' && value[0] != 'd' && value[0] != 'n'))
                badWord(loc, w, "expected c=a, c=d or c=n");
            s.colour = value[0] == 'a'   ? ColourMode::kAverage
                       : value[0] == 'd' ? ColourMode::kDistribution
                                         : ColourMode::kNone;
            return;
        case 'd':
            if (value.empty()) return;  // RADIANCE compat: "d=" leaves the density
            s.density = countValue(loc, w, "an integer density (BSDF input is not supported)");
            return;
        case 's':
            s.samples = countValue(loc, w, "an integer number of samples");
            return;
        case 'b': {
            double b = 0;
            if (!rp::parseReal(w.value, b)) badWord(loc, w, "expected a real brightness");
            s.minBrightness = b < 0 ? 0 : b;
            return;
        }
        case 'o':
            if (value.empty()) badWord(loc, w, "expected a file name");
            result.outputFile = value;
            return;
        default:
            badWord(loc, w, "unknown variable");
    }
}

}  // namespace

bool IllumSettings::selects(const std::string& modifier) const {
    switch (selection) {
        case Selection::kAll:
            return true;
        case Selection::kNone:
            return false;
        case Selection::kOnly:
            return modifier == selectModifier;
        case Selection::kAllBut:
            return modifier != selectModifier;
    }
    return false;
}

bool isOptionLine(std::string_view line) {
    return line.substr(0, kKeyword.size()) == kKeyword &&
           (line.size() == kKeyword.size() || isSpace(line[kKeyword.size()]));
}

OptionLine applyOptionLine(std::string_view line, IllumSettings& settings, const SourceLoc& loc) {
    OptionLine result;
    for (std::string_view text : splitWords(line.substr(kKeyword.size()))) {
        Word w{text, {}, text.size() >= 2 && text[1] == '='};
        if (w.assigns) w.value = text.substr(2);
        const char c = text[0];
        if (c == '!') {  // the rest of the line does not matter (RADIANCE stops here)
            result.processed = true;
            return result;
        }
        if (c == 'l') {
            if (text != "l+" && text != "l-") badWord(loc, w, "expected l+ or l-");
            settings.light = text == "l+";
        } else if (c == 'a' && !w.assigns) {  // RADIANCE compat: the word's first letter
            settings.selection = Selection::kAll;
        } else if (c == 'n' && !w.assigns) {
            settings.selection = Selection::kNone;
        } else if (w.assigns) {
            applyValue(loc, w, settings, result);
        } else {
            badWord(loc, w, "unknown variable");
        }
    }
    return result;
}

std::string formatSettings(const IllumSettings& s) {
    std::string out = formatLine("m=%-15s\t\t# material name\n", s.material.c_str());
    out += formatLine("f=%-15s\t\t# data file name\n", s.dataFile.c_str());
    switch (s.colour) {
        case ColourMode::kDistribution:
            out += "c=d\t\t\t\t# color distribution\n";
            break;
        case ColourMode::kAverage:
            out += "c=a\t\t\t\t# color average\n";
            break;
        case ColourMode::kNone:
            out += "c=n\t\t\t\t# color none\n";
            break;
    }
    out += s.light ? "l+\t\t\t\t# light type on\n" : "l-\t\t\t\t# light type off\n";
    out += formatLine("d=%d\t\t\t\t# density of directions\n", s.density);
    out += formatLine("s=%d\t\t\t\t# samples per direction\n", s.samples);
    out += formatLine("b=%f\t\t\t# minimum average brightness\n", s.minBrightness);
    return out;
}

}  // namespace rp::illum
