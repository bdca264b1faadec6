// What mkillum writes (RADIANCE mkillum3.c): primitives in RADIANCE mkillum's own layout,
// the brightdata/colordata patterns over illum.cal's coordinates, the illum or light
// materials, and the distributions' data files (ray.html "Data Files"; read back by
// calc/data_file.h). Deciding what to write is illum_filter.h.
#pragma once

#include <string>
#include <vector>

#include "illum/illum_input.h"
#include "illum/illum_sample.h"
#include "illum/illum_settings.h"
#include "util/color.h"

namespace rp::illum {

// RADIANCE mkillum3.c brt(): mkillum's own weights, not those of RADIANCE's bright().
inline double illumBrightness(const Color& c) { return .263 * c.r + .655 * c.g + .082 * c.b; }

// RADIANCE printobj: a blank line, then "modifier type name", the string arguments,
// "0" integer arguments and the reals three to a line (" %18.12g"); nothing for a
// surface modified by void, which mkillum drops.
std::string formatObject(const std::string& modifier, const InputObject& o);
// An alias: "\nmodifier alias name\told\n".
std::string formatAlias(const InputObject& o);

// The text of a data file over (altitude, azimuth): `rows` of `azimuths` values each,
// the first axis from `alt0` to `alt1`, the second from 0 to 2 pi with a column that
// repeats the first, five values a line as RADIANCE writes them (" %11e").
std::string formatDataFile(double alt0, double alt1, const std::vector<std::vector<double>>& rows);

// The name the next data file gets: f= name, channel letter (R, G or B; 0 for none),
// the file number if above 0, ".dat". Unless f= asked for clobbering, the number goes
// up past existing files (looked for in `directory`, "" the current one).
std::string nextDataFile(IllumSettings& s, char channel, const std::string& directory);

// Writes the data file(s) of a hemispherical distribution (RADIANCE flatout) into
// `directory` and returns the pattern that reads them, "<m>.dist" in frame `f`: one
// brightdata file normalised by the average brightness, or with c=d a colordata of three
// files normalised by the average's channels. The row before the first extrapolates the
// distribution across the pole (twice the first row's mean minus each value).
// Advances the file number.
std::string writeFlatDistribution(IllumSettings& s, const Distribution& d, const Color& average,
                                  const FlatFrame& f, const std::string& directory);
// The same over the whole sphere (RADIANCE roundout), extrapolated at both poles.
std::string writeRoundDistribution(IllumSettings& s, const Distribution& d, const Color& average,
                                   const std::string& directory);

// RADIANCE illumout: the illum (alternate material `alternate` unless void) or light
// material named m= with the average colour (its brightness in each channel with c=n),
// modified by the distribution unless d=0, then the surface modified by it.
std::string formatIllum(const IllumSettings& s, const std::string& alternate, const Color& average,
                        const InputObject& o);

}  // namespace rp::illum
