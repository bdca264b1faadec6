#include "material/chain_text.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "util/data_words.h"
#include "util/error.h"

namespace rp::material {

namespace {

bool toInt(const std::string& s, int& v) {
    if (s.empty()) return false;
    size_t k = (s[0] == '-' || s[0] == '+') ? 1 : 0;
    if (k == s.size()) return false;
    for (size_t j = k; j < s.size(); ++j)
        if (!std::isdigit((unsigned char)s[j])) return false;
    if (s.size() > 9) return false;
    v = std::stoi(s);
    return true;
}

}  // namespace

std::shared_ptr<Font> Font::parse(const std::string& text, const std::string& name) {
    auto font = std::make_shared<Font>();
    std::vector<DataWord> tok = splitDataWords(text);
    size_t k = 0;
    long widthSum = 0, count = 0;
    auto fail = [&](int line, const std::string& msg) {
        throw InputError(SourceLoc{name, line}, "font file: " + msg);
    };
    while (k < tok.size()) {
        int code = 0, n = 0;
        if (!toInt(tok[k].text, code)) fail(tok[k].line, "non-integer '" + tok[k].text + "'");
        if (code < 1 || code > 255) fail(tok[k].line, "illegal character code " + tok[k].text);
        if (font->glyphs[code]) fail(tok[k].line, "duplicate character " + tok[k].text);
        int codeLine = tok[k].line;
        if (++k >= tok.size() || !toInt(tok[k].text, n) || n < 0 || n > 32000)
            fail(k < tok.size() ? tok[k].line : codeLine,
                 "bad number of vertices for character " + std::to_string(code));
        ++k;
        auto g = std::make_unique<Glyph>();
        for (int v = 0; v < n; ++v) {
            std::array<int, 2> xy{};
            for (int c = 0; c < 2; ++c, ++k) {
                if (k >= tok.size() || !toInt(tok[k].text, xy[c]) || xy[c] < 0 || xy[c] > 255)
                    fail(k < tok.size() ? tok[k].line : codeLine,
                         "bad vertex for character " + std::to_string(code));
            }
            g->left = std::min(g->left, xy[0]);
            g->right = std::max(g->right, xy[0]);
            g->bottom = std::min(g->bottom, xy[1]);
            g->top = std::max(g->top, xy[1]);
            g->verts.push_back(xy);
        }
        if (g->right > g->left && g->top > g->bottom) {
            widthSum += g->right - g->left;
            ++count;
        }
        font->glyphs[code] = std::move(g);
    }
    if (count) font->meanWidth = int(widthSum / count);
    return font;
}

std::shared_ptr<Font> Font::load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open font file");
    std::ostringstream ss;
    ss << in.rdbuf();
    return parse(ss.str(), path);
}

bool insideGlyph(const Glyph* g, double x, double y) {
    if (!g || g->verts.empty()) return false;
    int xi = int(x), yi = int(y);
    if (g->left > xi || g->right <= xi || g->bottom > yi || g->top <= yi) return false;
    // Decide which edges straddle the test point on doubled coordinates with the point at
    // an odd value, so no vertex ever lies exactly on the test line.
    int xt = 2 * xi + 1, yt = 2 * yi + 1;
    size_t n = g->verts.size();
    int crossings = 0;
    for (size_t i = 0; i < n; ++i) {
        const auto& p0 = g->verts[(i + n - 1) % n];
        const auto& p1 = g->verts[i];
        if ((2 * p0[1] > yt) == (2 * p1[1] > yt)) continue;
        bool r0 = 2 * p0[0] > xt, r1 = 2 * p1[0] > xt;
        if (r0 && r1) {
            ++crossings;
        } else if (r0 || r1) {
            // The edge passes the point's row on one side or the other: which side.
            bool upward = p1[1] > p0[1];
            bool left = (p0[1] - y) * (p1[0] - x) > (p0[0] - x) * (p1[1] - y);
            crossings += upward != left ? 1 : 0;
        }
    }
    return crossings & 1;
}

int uniformSpacing(std::vector<short>& adv, const std::string& line, const Font& f) {
    adv.assign(line.size() + 1, 0);
    int width = 0;
    for (size_t i = 0; i < line.size(); ++i)
        if (f.glyph((unsigned char)line[i])) width += adv[i + 1] = 255;
    return width;
}

int squeezedSpacing(std::vector<short>& adv, const std::string& line, const Font& f, int gap) {
    adv.assign(line.size() + 2, 0);
    size_t t = 0, k = 0;
    int width = 0;
    const Glyph* g = nullptr;
    // Characters without glyphs take no room (RADIANCE compat: font.c squeeztext).
    while (t < line.size() && !(g = f.glyph((unsigned char)line[t++]))) adv[k++] = 0;
    int half = gap / 2;
    adv[k] = short(half);
    while (g) {
        if (!g->verts.empty()) {
            adv[k] = short(adv[k] + half - g->left);
            width += adv[k++];
            adv[k] = short(g->right + half);
        } else {  // a space: the mean glyph width
            width += adv[k++];
            adv[k] = short(f.meanWidth);
        }
        g = nullptr;
        while (t < line.size() && !(g = f.glyph((unsigned char)line[t++]))) {
            width += adv[k++];
            adv[k] = 0;
        }
    }
    adv[k] = short(adv[k] + half);
    width += adv[k];
    adv.resize(line.size() + 1);
    return width;
}

int proportionalSpacing(std::vector<short>& adv, const std::string& line, const Font& f, int gap,
                        int minIndent) {
    squeezedSpacing(adv, line, f, gap);
    auto glyphAt = [&](size_t i) {
        return i < line.size() ? f.glyph((unsigned char)line[i]) : nullptr;
    };
    int width = adv[0];
    size_t k = 1, t = 0, next = 0;
    // Each run of text up to a wide gap of spaces (an indent or tab stop) is stretched to
    // the mean glyph width plus gap per character, keeping later runs aligned.
    while (t < line.size()) {
        int len = 0, used = 0;
        size_t nk = k;
        for (size_t end = t; end < line.size(); end = next) {
            next = end + 1;
            used += adv[nk++];
            if (glyphAt(end)) {
                const Glyph* g;
                while ((g = glyphAt(next)) && g->verts.empty()) {
                    used += adv[nk++];
                    ++next;
                }
                len += int(next - end);
            }
            if (minIndent && int(next - end) > minIndent) break;
        }
        len *= f.meanWidth + gap;
        width += len;
        len -= used;
        while (k < nk) {
            int share = len / int(nk - k);
            adv[k++] += short(share);
            len -= share;
        }
        t = next;
    }
    return width;
}

TextBlock::TextBlock(std::shared_ptr<const Font> font, std::vector<std::string> lines, Vec3 origin,
                     Vec3 right, Vec3 down, bool hasSpacing, double spacing)
    : font_(std::move(font)), origin_(origin) {
    // Dual vectors: (p - origin) . rightDual counts characters along `right`, and
    // downDual lines along `down`, whatever the angle between them.
    Vec3 dxr = cross(down, right);
    rightDual_ = cross(dxr, down);
    double d = dot(rightDual_, rightDual_);
    if (d <= 1e-24) throw InputError("illegal motion vector");
    rightDual_ *= dot(down, down) / d;
    downDual_ = cross(right, dxr);
    downDual_ *= dot(right, right) / dot(downDual_, downDual_);
    int gap = int(spacing * 255.0);
    xScale_ = hasSpacing ? font_->meanWidth + 255.0 * std::fabs(spacing) : 255.0;
    for (std::string& s : lines) {
        Line l;
        l.text = std::move(s);
        if (gap < 0)
            l.width = squeezedSpacing(l.advance, l.text, *font_, -gap);
        else if (gap > 0)
            l.width = proportionalSpacing(l.advance, l.text, *font_, gap, 3);
        else
            l.width = uniformSpacing(l.advance, l.text, *font_);
        lines_.push_back(std::move(l));
    }
}

bool TextBlock::inText(const Vec3& p) const {
    Vec3 v = p - origin_;
    double x = dot(v, rightDual_) * xScale_;
    double y = dot(v, downDual_);
    if (x < 0 || y < 0) return false;
    int h = int(x);
    int lineNo = int(y);
    x -= h;
    y = ((lineNo + 1) - y) * 255.0;  // glyph y grows upwards from the line's base
    if (size_t(lineNo) >= lines_.size()) return false;
    const Line& l = lines_[size_t(lineNo)];
    if (h >= l.width) return false;
    for (size_t i = 0; i < l.advance.size() && (h -= l.advance[i]) >= 0; ++i)
        if (h < 255 && i < l.text.size() &&
            insideGlyph(font_->glyph((unsigned char)l.text[i]), h + x, y))
            return true;
    return false;
}

}  // namespace rp::material
