// A small bitmap font of our own for falsecolor's legend text: 5 x 7 glyphs (digits,
// letters and the signs numbers and units need) drawn at any height. No other text
// rendering here; the legend layout is falsecolor.h's.
#pragma once

#include <string_view>
#include <vector>

namespace rp {

// A text image: true where the glyph strokes are, row-major, top row first.
struct TextMask {
    int width = 0;
    int height = 0;
    std::vector<bool> on;
    bool at(int x, int y) const { return on[static_cast<size_t>(y) * width + x]; }
};

// Renders one line of text `height` pixels high (the glyph cell is 6 x 9 units: one unit
// of space right of each glyph, one above and one below, so lines never touch). Glyphs
// not in the font are drawn as '?'. Width is the number of characters times the cell
// width, rounded; with maxWidth > 0 a wider text is narrowed to maxWidth (the glyphs
// keep their height), so that a long label still fits its legend.
TextMask renderText(std::string_view text, int height, int maxWidth = 0);

}  // namespace rp
