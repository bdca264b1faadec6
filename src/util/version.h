// radphoton's name and version as the tools print them: the SOFTWARE= line of picture
// headers and the line every tool's -version prints.
#pragma once

#include <string>

namespace rp {

// "radphoton 0.1": what picture headers name in their SOFTWARE= line.
std::string softwareName();

// The -version line. It starts as RADIANCE 5.4's does ("RADIANCE 5.4a <date> ..."),
// because scripts that check for RADIANCE (honeybee-radiance runs `rtrace -version`,
// pyradiance `rtrace -version`) read the second word as the version and the third as a
// date; radphoton's own version and the commit it was built from follow, e.g.
// "RADIANCE 5.4a 2026-12-06 radphoton 0.1 (7f52428bd1)".
std::string versionLine();

// The RADIANCE release whose tools, options and file formats radphoton follows.
constexpr const char* kRadianceLevel = "5.4a";

}  // namespace rp
