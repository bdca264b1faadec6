// EPW to WEA conversion (see epw.h). The numbers are formatted with C's printf and
// converted with C's atoi/atof/strtof, so every digit (and every "-0") is epw2wea's.
#include "gen/epw.h"

#include <cstdlib>
#include <iterator>
#include <vector>

#include "gen/gen_text.h"
#include "util/error.h"

namespace rp::gen {

namespace {

struct Line {
    std::string text;  // without the line end
    int number = 0;
};

// Lines with their numbers; blank lines (only line-end characters) are dropped, as
// epw2wea's "%*[\n\r]" swallows them between lines.
std::vector<Line> splitLines(const std::string& text) {
    std::vector<Line> lines;
    size_t start = 0;
    int number = 1;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string s = text.substr(start, end - start);
        while (!s.empty() && s.back() == '\r') s.pop_back();
        if (!s.empty()) lines.push_back({s, number});
        ++number;
        start = end + 1;
    }
    return lines;
}

std::vector<std::string> splitFields(const std::string& s) {
    std::vector<std::string> fields;
    size_t start = 0;
    for (;;) {
        size_t comma = s.find(',', start);
        fields.push_back(
            s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return fields;
        start = comma + 1;
    }
}

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r'; }

// A whole field as C's %d or %f reads it (leading blanks allowed, nothing after).
bool scanInt(const std::string& field, int& value) {
    const char* s = field.c_str();
    char* end = nullptr;
    long v = std::strtol(s, &end, 10);
    if (end == s) return false;
    while (isBlank(*end)) ++end;
    value = static_cast<int>(v);
    return *end == '\0';
}
bool scanFloat(const std::string& field, float& value) {
    const char* s = field.c_str();
    char* end = nullptr;
    value = std::strtof(s, &end);
    if (end == s) return false;
    while (isBlank(*end)) ++end;
    return *end == '\0';
}

// RADIANCE compat (epw2wea.c): an empty field leaves the previous value in place.
void keepUnlessEmpty(std::string& into, const std::string& field) {
    if (!field.empty()) into = field;
}

struct Location {
    std::string city, country, latitude, longitude, timeZone, elevation;
};

Location readLocation(const Line& line, const std::string& name) {
    std::vector<std::string> f = splitFields(line.text);
    if (f[0] != "LOCATION")
        throw InputError(SourceLoc{name, line.number},
                         "this does not seem to be an epw file (no LOCATION line)");
    if (f.size() < 10)
        throw InputError(SourceLoc{name, line.number},
                         "LOCATION line has " + std::to_string(f.size()) + " fields, expected 10");
    Location loc;
    keepUnlessEmpty(loc.city, f[1]);
    keepUnlessEmpty(loc.country, f[2]);  // state or province
    keepUnlessEmpty(loc.country, f[3]);
    keepUnlessEmpty(loc.latitude, f[6]);
    keepUnlessEmpty(loc.longitude, f[7]);
    keepUnlessEmpty(loc.timeZone, f[8]);
    // RADIANCE compat: the elevation is read with "%s": the first blank-free word after
    // the ninth comma, commas included.
    size_t at = 0;
    for (int commas = 0; commas < 9; ++commas) at = line.text.find(',', at) + 1;
    while (at < line.text.size() && isBlank(line.text[at])) ++at;
    size_t end = at;
    while (end < line.text.size() && !isBlank(line.text[end])) ++end;
    loc.elevation = line.text.substr(at, end - at);
    if (loc.elevation.empty())
        throw InputError(SourceLoc{name, line.number}, "LOCATION line has no elevation");
    return loc;
}

// "DATA PERIODS,n,records per hour,...": epw2wea's "minute".
int readInterval(const Line& line, const std::string& name) {
    std::vector<std::string> f = splitFields(line.text);
    if (f[0] != "DATA PERIODS" || f.size() < 3)
        throw InputError(SourceLoc{name, line.number},
                         "expected 'DATA PERIODS,count,records per hour,...' as the 8th line");
    int minute = std::atoi(f[2].c_str());
    // RADIANCE compat (epw2wea.c): one record per hour is a 60 minute step; any other
    // count is used as the step in minutes as it stands.
    return minute == 1 ? 60 : minute;
}

std::string recordLine(const Line& line, int minute, const std::string& name) {
    auto fail = [&](const std::string& m) { throw InputError(SourceLoc{name, line.number}, m); };
    std::vector<std::string> f = splitFields(line.text);
    if (f.size() < 16)
        fail("record has " + std::to_string(f.size()) + " fields, expected at least 16");
    int year = 0, month = 0, day = 0, hour = 0;
    if (!scanInt(f[0], year) || !scanInt(f[1], month) || !scanInt(f[2], day) ||
        !scanInt(f[3], hour))
        fail("expected year, month, day and hour as whole numbers");
    float direct = 0, diffuse = 0;
    if (!scanFloat(f[14], direct) || !scanFloat(f[15], diffuse))
        fail("expected direct normal and diffuse horizontal radiation (fields 15, 16) as numbers");
    return cformat("%d %d %.3f ", month, day, hour * 1.0 - minute * (0.5 / 60)) +
           cformat("%.0f %.0f", direct, diffuse) + "\n";
}

}  // namespace

EpwConversion epwToWea(std::istream& in, const std::string& name) {
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw InputError(SourceLoc{name, 0}, "read error");
    std::vector<Line> lines = splitLines(text);
    if (lines.empty())
        throw InputError(SourceLoc{name, 0}, "this does not seem to be an epw file (empty)");
    Location loc = readLocation(lines[0], name);
    if (lines.size() < 8)
        throw InputError(SourceLoc{name, lines.back().number},
                         "the file ends inside the 8 header lines");
    int minute = readInterval(lines[7], name);

    std::string head = "place " + loc.city + "_" + loc.country + "\n";
    head += "latitude " + loc.latitude + "\n";
    head += cformat("longitude %.2f\n", -1.0 * std::atof(loc.longitude.c_str()));
    EpwConversion out;
    // RADIANCE compat (epw2wea.c): the console shows the time zone from atof with two
    // decimals, the file from atoi with none.
    out.console = head + cformat("time_zone %.2f\n", -15.0 * std::atof(loc.timeZone.c_str()));
    out.wea = head + cformat("time_zone %.0f\n", -15.0 * std::atoi(loc.timeZone.c_str()));
    std::string tail = "site_elevation " + loc.elevation + "\nweather_data_file_units 1\n";
    out.console += tail;
    out.wea += tail;
    for (size_t i = 8; i < lines.size(); ++i) out.wea += recordLine(lines[i], minute, name);
    return out;
}

}  // namespace rp::gen
