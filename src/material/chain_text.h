// Text patterns (colortext, brighttext, mixtext; ray.html "Patterns", "Font Files"):
// RADIANCE polygon fonts and a block of text lines laid out on a plane by the record's
// origin, right and down vectors. Answers one question: is a point inside a glyph?
// Colours and modifier choice are the caller's (surface_chain).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "util/vec.h"

namespace rp::material {

// A polygon font: per character code 1..255 one polygon (holes joined by seams) on the
// 0..255 character grid.
struct Glyph {
    std::vector<std::array<int, 2>> verts;
    int left = 128, right = 128, bottom = 128, top = 128;  // extent
};

struct Font {
    std::array<std::unique_ptr<Glyph>, 256> glyphs;  // null: no such character
    int meanWidth = 0;  // RADIANCE mwidth: mean extent width of the non-empty glyphs

    // Parses font text; `name` for messages. Throws InputError naming file and line.
    static std::shared_ptr<Font> parse(const std::string& text, const std::string& name);
    static std::shared_ptr<Font> load(const std::string& path);
    const Glyph* glyph(unsigned char c) const { return glyphs[c].get(); }
};

// True if (x, y), in character grid units [0,255), is inside the glyph. RADIANCE compat
// (text.c inglyph): the extent test and crossing test use the centre of the grid cell.
bool insideGlyph(const Glyph* g, double x, double y);

class TextBlock {
public:
    // `origin`, `right`, `down`: the record's Ox..Dz (upper left corner of the block and
    // the motion vectors of one character and one line). `spacing` < 0: squeezed, > 0:
    // proportional, 0: uniform; `hasSpacing`: the optional argument was given. Throws
    // InputError (message only) for parallel or zero motion vectors.
    TextBlock(std::shared_ptr<const Font> font, std::vector<std::string> lines, Vec3 origin,
              Vec3 right, Vec3 down, bool hasSpacing, double spacing);

    // Whether point p (in the pattern's space) falls inside a glyph of the text.
    bool inText(const Vec3& p) const;

    int lineWidth(size_t line) const { return lines_.at(line).width; }
    const std::vector<short>& spacing(size_t line) const { return lines_.at(line).advance; }

private:
    struct Line {
        std::string text;
        std::vector<short> advance;  // [i]: start of char i relative to char i-1 (size n+1)
        int width = 0;
    };
    std::shared_ptr<const Font> font_;
    std::vector<Line> lines_;
    Vec3 origin_, rightDual_, downDual_;
    double xScale_ = 255;
};

// Character spacing of one line (RADIANCE font.c): uniform cells of 255, squeezed
// (glyph extents plus `gap`), or proportional (squeezed, then words spread to a mean
// width per character, keeping runs of more than `minIndent` spaces as tab stops).
// Return the line width; `advance` gets n+1 entries.
int uniformSpacing(std::vector<short>& advance, const std::string& line, const Font& f);
int squeezedSpacing(std::vector<short>& advance, const std::string& line, const Font& f, int gap);
int proportionalSpacing(std::vector<short>& advance, const std::string& line, const Font& f,
                        int gap, int minIndent);

}  // namespace rp::material
