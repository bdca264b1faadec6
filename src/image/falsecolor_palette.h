// The colour scales of RADIANCE's falsecolor (def, spec, pm3d, hot, eco, tbo): each maps
// a value v (0 at the bottom of the scale, 1 at its top) to red, green and blue. The
// legend, contours and picture composition live in falsecolor.h.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rp {

enum class FalseColorPalette { kDef, kSpec, kPm3d, kHot, kEco, kTbo };

// Names in RADIANCE's order (falsecolor -palettes draws them bottom to top).
const std::vector<std::string>& paletteNames();
std::optional<FalseColorPalette> paletteByName(std::string_view name);

// The palette's colour at v, each component clipped to [0,1] as falsecolor's output
// expressions clip them. Values outside [0,1] take the palette's end colours (def, tbo)
// or its formulas' continuation before clipping (spec), as RADIANCE's do.
std::array<double, 3> paletteColor(FalseColorPalette p, double v);

}  // namespace rp
