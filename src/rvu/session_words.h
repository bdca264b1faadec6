// Small helpers shared by the session's command files: words, numbers and results.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "image/rgbe.h"
#include "rvu/session.h"
#include "util/command_args.h"
#include "util/error.h"

namespace rp::rvu {

// Words as RADIANCE's nextword reads them: white space separates, quotes may hold it.
using rp::splitWords;

inline std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

// A whole word as a finite number; InputError naming `what` otherwise. Stricter than
// RADIANCE's sscanf, which reads "2x" as 2 and silently ignores "x2".
inline double number(const std::string& word, const char* what) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (word.empty() || *end || !std::isfinite(v))
        throw InputError(std::string("bad number '") + word + "' for " + what);
    return v;
}

inline CommandResult success(std::string output) {
    CommandResult r;
    r.output = std::move(output);
    return r;
}

inline CommandResult failure(std::string error) {
    CommandResult r;
    r.ok = false;
    r.error = std::move(error);
    return r;
}

inline CommandResult pickRequest(std::string prompt, int points) {
    CommandResult r;
    r.ok = false;
    r.pick = std::move(prompt);
    r.points = points;
    return r;
}

inline Cursor clampCursor(Cursor c, int width, int height) {
    return {std::clamp(c.x, 0, width - 1), std::clamp(c.y, 0, height - 1)};
}

inline Pixel averagePixel(const std::vector<Pixel>& pixels) {
    double sum[3] = {0, 0, 0};
    for (const Pixel& p : pixels)
        for (int c = 0; c < 3; ++c) sum[c] += p[c];
    const double n = double(std::max<size_t>(1, pixels.size()));
    return Pixel{float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
}

}  // namespace rp::rvu
