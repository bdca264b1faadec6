// Scene text lexer and RADIANCE number syntax (see lexer.h).
#include "scene/lexer.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace rp {

namespace {
bool isWhite(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

bool parseInteger(std::string_view w, long& out) {
    size_t i = 0;
    if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
    if (i == w.size()) return false;
    for (size_t k = i; k < w.size(); ++k)
        if (!isDigit(w[k])) return false;
    std::string s(w);
    errno = 0;
    out = std::strtol(s.c_str(), nullptr, 10);
    return errno == 0;
}

bool parseReal(std::string_view w, double& out) {
    // Checked by hand first: strtod alone would also take "inf", "nan", hex floats and
    // trailing garbage, none of which RADIANCE's readfargs() accepts.
    size_t i = 0;
    if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
    size_t digits = 0;
    while (i < w.size() && isDigit(w[i])) ++i, ++digits;
    if (i < w.size() && w[i] == '.') {
        ++i;
        while (i < w.size() && isDigit(w[i])) ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < w.size() && (w[i] == 'e' || w[i] == 'E')) {
        ++i;
        if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
        size_t expDigits = 0;
        while (i < w.size() && isDigit(w[i])) ++i, ++expDigits;
        if (expDigits == 0) return false;
    }
    if (i != w.size()) return false;
    std::string s(w);
    out = std::strtod(s.c_str(), nullptr);
    // Beyond double range: RADIANCE takes +-HUGE_VAL, and an infinite coordinate then
    // crashes its oconv; refused here, at the word's line.
    return std::isfinite(out);
}

bool SceneLexer::skipSpace() {
    while (pos_ < text_.size() && isWhite(text_[pos_])) {
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
    }
    return pos_ < text_.size();
}

void SceneLexer::skipComment() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
}

std::string SceneLexer::readCommand() {
    std::string cmd;
    if (pos_ < text_.size() && text_[pos_] == '!') ++pos_;
    while (pos_ < text_.size()) {
        char c = text_[pos_];
        if (c == '\\' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') {
            pos_ += 2;  // RADIANCE ray.html: "a command may be continued ... using a backslash"
            ++line_;
            continue;
        }
        if (c == '\n') break;  // the newline itself is left for skipSpace to count
        cmd.push_back(c);
        ++pos_;
    }
    return cmd;
}

bool SceneLexer::readWord(std::string& word, int& line) {
    word.clear();
    if (!skipSpace()) return false;
    line = line_;
    char quote = text_[pos_];
    if (quote == '"' || quote == '\'') {
        ++pos_;
        while (pos_ < text_.size() && text_[pos_] != quote) {
            if (text_[pos_] == '\n') ++line_;
            word.push_back(text_[pos_++]);
        }
        if (pos_ == text_.size()) return false;  // unterminated quote
        ++pos_;
        return true;
    }
    while (pos_ < text_.size() && !isWhite(text_[pos_])) word.push_back(text_[pos_++]);
    return true;
}

}  // namespace rp
