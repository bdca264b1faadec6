// Weather tape reading (see wea.h): a small scanner that keeps line numbers for messages.
#include "gen/wea.h"

#include <cctype>
#include <iterator>
#include <optional>

#include "gen/sun_position.h"
#include "util/error.h"
#include "util/options.h"

namespace rp::gen {

namespace {

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

class TapeScanner {
public:
    TapeScanner(std::string text, std::string name)
        : text_(std::move(text)), name_(std::move(name)) {}

    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(SourceLoc{name_, line_}, message);
    }
    void skipSpace() {
        while (pos_ < text_.size() && isSpace(text_[pos_])) {
            if (text_[pos_] == '\n') ++line_;
            ++pos_;
        }
    }
    bool keyword(const std::string& word) {
        if (text_.compare(pos_, word.size(), word) != 0) return false;
        pos_ += word.size();
        return true;
    }
    // The next white-space separated word on the tape (possibly on a later line).
    std::string word() {
        skipSpace();
        size_t start = pos_;
        while (pos_ < text_.size() && !isSpace(text_[pos_])) ++pos_;
        return text_.substr(start, pos_ - start);
    }
    // Up to the end of the line (RADIANCE's "%[^\r\n]").
    std::string restOfLine() {
        size_t start = pos_;
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
        return text_.substr(start, pos_ - start);
    }
    bool atEnd() const { return pos_ >= text_.size(); }
    int line() const { return line_; }
    const std::string& name() const { return name_; }

private:
    std::string text_;
    std::string name_;
    size_t pos_ = 0;
    int line_ = 1;
};

[[noreturn]] void headerError(const TapeScanner& s, const std::string& what) {
    s.fail("weather tape format error in header: expected " + what);
}

double headerValue(TapeScanner& s, const std::string& keyword, const std::string& what) {
    s.skipSpace();
    if (!s.keyword(keyword)) headerError(s, "'" + keyword + " " + what + "'");
    std::optional<double> v = rp::parseReal(s.word());
    if (!v) headerError(s, "'" + keyword + " " + what + "'");
    return *v;
}

WeaHeader readHeader(TapeScanner& s) {
    WeaHeader h;
    // RADIANCE compat: "place" must open the tape; the name runs to the end of its line.
    if (!s.keyword("place")) headerError(s, "'place name' on the first line");
    s.skipSpace();
    h.place = s.restOfLine();
    if (h.place.empty()) headerError(s, "'place name' on the first line");
    h.latitude = headerValue(s, "latitude", "<degrees north>");
    h.longitude = headerValue(s, "longitude", "<degrees west>");
    h.timeZone = headerValue(s, "time_zone", "<meridian degrees west>");
    h.elevation = headerValue(s, "site_elevation", "<metres>");
    s.skipSpace();
    if (!s.keyword("weather_data_file_units")) headerError(s, "'weather_data_file_units 1|2|3'");
    std::optional<long> units = rp::parseInteger(s.word());
    if (!units || *units < 1 || *units > 3)
        s.fail("weather tape format error in header: weather_data_file_units must be 1, 2 or 3");
    h.units = static_cast<WeaUnits>(*units);
    return h;
}

// One record line's words: month day hour direct diffuse.
WeaRecord readRecord(const std::vector<std::string>& words, const TapeScanner& s, int line) {
    auto fail = [&](const std::string& m) { throw InputError(SourceLoc{s.name(), line}, m); };
    if (words.size() != 5)
        fail("expected 'month day hour direct diffuse', got " + std::to_string(words.size()) +
             " words");
    std::optional<long> month = rp::parseInteger(words[0]), day = rp::parseInteger(words[1]);
    std::optional<double> hour = rp::parseReal(words[2]), dir = rp::parseReal(words[3]),
                          dif = rp::parseReal(words[4]);
    if (!month || !day || !hour || !dir || !dif)
        fail("expected 'month day hour direct diffuse' as numbers");
    WeaRecord r{static_cast<int>(*month), static_cast<int>(*day), *hour, *dir, *dif, line};
    try {
        checkDate(r.month, r.day);
    } catch (const InputError& e) {
        fail(e.message());
    }
    return r;
}

}  // namespace

WeaTape readWea(std::istream& in, const std::string& name) {
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw InputError(SourceLoc{name, 0}, "read error");
    TapeScanner s(std::move(text), name);
    WeaTape tape;
    tape.header = readHeader(s);
    // Records, one per line (RADIANCE reads them as a stream of words; a line at a time
    // lets a message name the line).
    s.skipSpace();
    while (!s.atEnd()) {
        int line = s.line();
        std::vector<std::string> words;
        std::string rest = s.restOfLine();
        size_t i = 0;
        while (i < rest.size()) {
            while (i < rest.size() && isSpace(rest[i])) ++i;
            size_t start = i;
            while (i < rest.size() && !isSpace(rest[i])) ++i;
            if (i > start) words.push_back(rest.substr(start, i - start));
        }
        tape.records.push_back(readRecord(words, s, line));
        s.skipSpace();
    }
    return tape;
}

}  // namespace rp::gen
