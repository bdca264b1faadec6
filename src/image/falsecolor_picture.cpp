// falsecolor's picture composition (see falsecolor.h): the mapped image, the legend's
// colour bar and text, extrema labels, placed as RADIANCE's falsecolor.pl has pcompos
// place them, and the tool's file handling.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <istream>
#include <ostream>

#include "image/falsecolor.h"
#include "image/legend_font.h"
#include "image/spectral_picture.h"
#include "util/error.h"

namespace rp {

namespace {

constexpr double kRedWeight = 0.265074126;  // RADIANCE's bright() (color.h)
constexpr double kGreenWeight = 0.670114631;
constexpr double kBlueWeight = 0.064811243;

double bright(const Pixel& p) {
    return kRedWeight * p[0] + kGreenWeight * p[1] + kBlueWeight * p[2];
}

// One picture placed in pcompos's frame: (x, y) is its lower-left corner, y upwards.
// `keep` says which of its pixels are copied (pcompos's -t/+t thresholds).
struct Layer {
    Picture pic;
    int x = 0;
    int y = 0;
    std::function<bool(const Pixel&)> keep;
};

// pcompos: the output spans from 0 to the farthest right and top edge of any layer;
// later layers cover earlier ones; the background is black.
Picture composeLayers(const std::vector<Layer>& layers) {
    int xsize = 0, ysize = 0;
    for (const Layer& l : layers) {
        xsize = std::max(xsize, l.x + l.pic.width);
        ysize = std::max(ysize, l.y + l.pic.height);
    }
    Picture out(xsize, ysize);
    for (const Layer& l : layers) {
        for (int r = 0; r < l.pic.height; ++r) {
            int oy = ysize - (l.y + l.pic.height) + r;  // top-down output row
            if (oy < 0 || oy >= ysize) continue;
            for (int c = 0; c < l.pic.width; ++c) {
                int ox = l.x + c;
                if (ox < 0 || ox >= xsize) continue;
                const Pixel& p = l.pic.at(c, r);
                if (!l.keep || l.keep(p)) out.at(ox, oy) = p;
            }
        }
    }
    return out;
}

// pcompos's cmpcolr compares normbright() of the packed pixel, so thresholds see the
// RGBE-rounded value.
double packedBright(const Pixel& p) { return bright(toPixel(toColr(p))); }

Picture textPicture(const std::string& text, int height, Pixel ink, Pixel paper, int maxWidth = 0) {
    TextMask m = renderText(text, height, maxWidth);
    Picture p(std::max(m.width, 1), height);
    for (int y = 0; y < m.height; ++y)
        for (int x = 0; x < p.width; ++x) p.at(x, y) = (x < m.width && m.at(x, y)) ? ink : paper;
    return p;
}

// falsecolor.pl's legend geometry (all from -lw, -lh, -n).
struct LegendGeometry {
    int sheight = 0;       // height of one division
    int textHeight = 0;    // psign -h
    double barExtent = 0;  // pcomb's yres for the bar (may be fractional)
    int barRows = 0;       // rows pcomb writes: yres rounded
    int barY = 0;          // bar's lower edge (negative: partly below the picture)
};

LegendGeometry legendGeometry(const FalseColorOptions& o) {
    LegendGeometry g;
    g.sheight = o.legendHeight / o.ndivs;
    int theight = static_cast<int>(std::floor(o.legendWidth / (8 / 1.67)));
    g.textHeight = std::min(g.sheight, theight);
    g.barExtent = g.sheight * o.ndivs * (1 + 1.5 / o.ndivs);
    g.barRows = static_cast<int>(g.barExtent + 0.5);
    // RADIANCE compat: the bar starts half a division below the picture (a division and
    // a half with contours, where the bottom division carries no colour).
    g.barY =
        o.contour == ContourMode::kNone
            ? -static_cast<int>(std::floor(o.legendHeight / o.ndivs / 2.0))
            : -static_cast<int>(std::floor(o.legendHeight / static_cast<double>(o.ndivs) * 1.5));
    return g;
}

Picture legendBar(const FalseColorOptions& o, const LegendGeometry& g, FalseColorMap& map) {
    Picture bar(o.legendWidth, g.barRows);
    double span = g.barExtent / (1 + 1.5 / o.ndivs);
    for (int r = 0; r < g.barRows; ++r) {
        double y = g.barRows - 1 - r;  // pcomb's y counts from the bottom
        double v = (y + 0.5 - g.sheight) / span;
        bool in = true;
        if (o.contour == ContourMode::kLines) {
            double below = (y - 0.5 - g.sheight) / span, above = (y + 1.5 - g.sheight) / span;
            in = map.onLine(v, v, v, above, below);
        } else if (o.contour == ContourMode::kBands) {
            in = map.inBand(v);
        }
        auto c = in ? map.color(v) : std::array<double, 3>{0, 0, 0};
        Pixel px{static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
        for (int x = 0; x < bar.width; ++x) bar.at(x, r) = px;
    }
    return bar;
}

// The division values and the unit label, white, with a black drop shadow 2 right and
// 1 down (falsecolor.pl inverts the label picture and copies its dark pixels first).
void addLegendText(const FalseColorOptions& o, const LegendGeometry& g,
                   std::vector<Layer>& layers) {
    std::vector<std::string> texts = {o.label};
    for (const std::string& s : legendValues(o)) texts.push_back(s);
    int count = static_cast<int>(texts.size()) - 1;  // divisions labelled
    const Pixel white{1, 1, 1}, black{0, 0, 0};
    std::vector<Layer> shadows, inks;
    for (int i = 0; i < static_cast<int>(texts.size()); ++i) {
        // Label i-1 centred on sheight*(count-i) + sheight/2 (the unit label at i = 0 one
        // division above the top value); pcompos reads the position with atoi.
        int centre = static_cast<int>(g.sheight * (count - i) + g.sheight * 0.5);
        int y = centre - g.textHeight / 2;
        // pcompos thresholds: -t .5 keeps the white strokes, +t .1 the inverted ones.
        // Our font is wider than RADIANCE's proportional one: long values are narrowed
        // to the legend's width (less the shadow's offset) instead of being cut.
        const int room = std::max(1, o.legendWidth - 2);
        shadows.push_back({textPicture(texts[i], g.textHeight, black, white, room), 2, y - 1,
                           [](const Pixel& p) { return packedBright(p) < 0.1; }});
        inks.push_back({textPicture(texts[i], g.textHeight, white, black, room), 0, y,
                        [](const Pixel& p) { return packedBright(p) > 0.5; }});
    }
    for (Layer& l : shadows) layers.push_back(std::move(l));
    for (Layer& l : inks) layers.push_back(std::move(l));
}

// The mapped image: pcomb over every pixel with falsecolor.pl's pc0.cal and pc1.cal.
Picture mapImage(const Picture& in, const Picture* background, const FalseColorOptions& o,
                 FalseColorMap& map) {
    auto cc = in.colorCorrection();
    double e = in.exposure();
    // norm = mult/scale/le(1): le() is bright() of the exposure times colour correction.
    double norm = o.multiplier / o.scale /
                  (kRedWeight * e * cc[0] + kGreenWeight * e * cc[1] + kBlueWeight * e * cc[2]);
    int w = in.width, h = in.height;
    std::vector<double> v(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            v[static_cast<size_t>(y) * w + x] = map.position(bright(in.at(x, y)) * norm);
    // pcomb's li(1, dx, dy) clamps neighbours to the picture.
    auto at = [&](int x, int y) {
        x = std::clamp(x, 0, w - 1);
        y = std::clamp(y, 0, h - 1);
        return v[static_cast<size_t>(y) * w + x];
    };
    Picture out(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            double vi = at(x, y);
            bool draw = true;
            if (o.contour == ContourMode::kLines)
                draw = map.onLine(vi, at(x - 1, y), at(x + 1, y), at(x, y - 1), at(x, y + 1));
            else if (o.contour == ContourMode::kBands)
                draw = map.inBand(vi);
            if (draw) {
                auto c = map.color(vi);
                out.at(x, y) = {static_cast<float>(c[0]), static_cast<float>(c[1]),
                                static_cast<float>(c[2])};
            } else if (background) {
                out.at(x, y) = background->at(x, y);
            }
        }
    }
    return out;
}

// RADIANCE's pextrem: the darkest and brightest pixel compared as packed RGBE (exponent
// first, then normbright), scanning bottom to top and right to left; coordinates from
// the lower left.
struct Extreme {
    int x = 0, y = 0;
    Colr c{};
};

int normBright(const Colr& c) {
    return static_cast<int>((static_cast<long>(kRedWeight * 256 + 0.5) * c[0] +
                             static_cast<long>(kGreenWeight * 256 + 0.5) * c[1] +
                             static_cast<long>(kBlueWeight * 256 + 0.5) * c[2]) >>
                            8);
}

std::pair<Extreme, Extreme> findExtrema(const Picture& in) {
    Extreme lo, hi;
    lo.c = toColr(1e30f, 1e30f, 1e30f);
    hi.c = toColr(0.f, 0.f, 0.f);
    for (int row = 0; row < in.height; ++row) {  // pextrem reads the top scanline first
        int y = in.height - 1 - row;
        for (int x = in.width - 1; x >= 0; --x) {
            Colr c = toColr(in.at(x, row));
            if (c[3] > hi.c[3] || (c[3] == hi.c[3] && normBright(c) > normBright(hi.c)))
                hi = {x, y, c};
            if (c[3] < lo.c[3] || (c[3] == lo.c[3] && normBright(c) < normBright(lo.c)))
                lo = {x, y, c};
        }
    }
    return {lo, hi};
}

// The extremum's value as falsecolor.pl labels it: pextrem prints the components with
// %.2e (over the exposure), the script weights them .27/.67/.06 and multiplies.
std::string extremeLabel(const Extreme& ex, double exposure, const FalseColorOptions& o) {
    Pixel p = toPixel(ex.c);
    double rgb[3];
    for (int i = 0; i < 3; ++i) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2e", p[i] / exposure);
        rgb[i] = std::strtod(buf, nullptr);
    }
    return legendNumber((rgb[0] * .27 + rgb[1] * .67 + rgb[2] * .06) * o.multiplier, o.decimals);
}

void addExtrema(const Picture& in, const FalseColorOptions& o, std::vector<Layer>& layers) {
    auto [lo, hi] = findExtrema(in);
    const Pixel black{0, 0, 0}, white{1, 1, 1};
    for (const Extreme* ex : {&lo, &hi}) {
        // psign -h 16 defaults: black text on white.
        Picture t = textPicture(extremeLabel(*ex, in.exposure(), o), 16, black, white);
        layers.push_back({std::move(t), ex->x + o.legendWidth, ex->y, {}});
    }
}

// RADIANCE's phisto reduces the picture to fit 128 x 128 (pfilt); we average boxes of
// whole pixels, which is close to pfilt's one-pass box filter.
std::vector<double> reducedLuminances(const Picture& pic) {
    int f = std::max(1, static_cast<int>(std::ceil(std::max(pic.width, pic.height) / 128.0)));
    std::vector<double> out;
    for (int y0 = 0; y0 + f <= pic.height || (y0 == 0 && pic.height < f); y0 += f)
        for (int x0 = 0; x0 + f <= pic.width || (x0 == 0 && pic.width < f); x0 += f) {
            double sum = 0;
            int n = 0;
            for (int y = y0; y < std::min(pic.height, y0 + f); ++y)
                for (int x = x0; x < std::min(pic.width, x0 + f); ++x, ++n)
                    sum += bright(pic.at(x, y));
            out.push_back(sum / n / pic.exposure());
        }
    return out;
}

}  // namespace

double autoScaleTop(const Picture& pic, double multiplier) {
    double lmax = 0;
    for (double b : reducedLuminances(pic)) lmax = std::max(lmax, b * 179);
    if (!(lmax > 1e-7)) throw InputError("-s a: the picture is black");
    double lmin = 1e30;
    for (double b : reducedLuminances(pic)) lmin = std::min(lmin, b * 179);
    double lo = lmin > 1e-7 ? std::log10(lmin) - .01 : -7;
    double hi = std::log10(lmax) + .01;
    // histo's second-highest of 777 bins, its centre printed with %g.
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", lo + (hi - lo) * 775.5 / 777);
    return multiplier / 179 * std::pow(10.0, std::strtod(buf, nullptr));
}

Picture falseColorPicture(const Picture& input, const Picture* background, FalseColorOptions o,
                          const std::string& commandLine) {
    if (background && (background->width != input.width || background->height != input.height))
        throw InputError("background picture is " + std::to_string(background->width) + "x" +
                         std::to_string(background->height) + ", input " +
                         std::to_string(input.width) + "x" + std::to_string(input.height));
    if (o.autoScale) o.scale = autoScaleTop(input, o.multiplier);
    // RADIANCE compat: a legend too small to read is left out (falsecolor.pl).
    if (o.legendWidth <= 20 || o.legendHeight <= 40) o.legendWidth = o.legendHeight = 0;
    FalseColorMap map(o);
    std::vector<Layer> layers;
    if (o.legendWidth > 0) {
        LegendGeometry g = legendGeometry(o);
        layers.push_back({legendBar(o, g, map), 0, g.barY, {}});
        addLegendText(o, g, layers);
    }
    layers.push_back({mapImage(input, background, o, map), o.legendWidth, 0, {}});
    if (o.extrema) addExtrema(input, o, layers);
    Picture out = composeLayers(layers);
    for (const std::string& line : input.header.lines) out.header.lines.push_back("\t" + line);
    out.header.lines.push_back(commandLine);
    return out;
}

Picture paletteChart(const std::string& commandLine) {
    std::vector<Layer> layers;
    int y = 0;
    for (const std::string& name : paletteNames()) {
        FalseColorOptions o;
        o.palette = *paletteByName(name);
        FalseColorMap map(o);
        Picture strip(256, 30);
        for (int x = 0; x < 256; ++x) {
            auto c = map.paletteAt(x / 256.0);
            for (int r = 0; r < 30; ++r)
                strip.at(x, r) = {static_cast<float>(c[0]), static_cast<float>(c[1]),
                                  static_cast<float>(c[2])};
        }
        layers.push_back({std::move(strip), 0, y, {}});
        layers.push_back({textPicture(name, 20, {1, 1, 1}, {0, 0, 0}), 0, y + 30, {}});
        y += 50;
    }
    Picture out = composeLayers(layers);
    out.header.lines.push_back(commandLine);
    return out;
}

void runFalseColor(const FalseColorOptions& opt, const std::string& commandLine, std::istream& in,
                   std::ostream& out) {
    if (opt.showPalettes) {
        writePicture(out, paletteChart(commandLine));
        return;
    }
    auto load = [&](const std::string& name) {
        // A spectral picture is read as RADIANCE 6's ra_rgbe turns it into RGBE.
        constexpr auto how = SpectralToRgb::kBandAveragesRgbe;
        return name == "-" ? readPictureAsRgb(in, "<stdin>", how) : readPictureAsRgb(name, how);
    };
    Picture input = load(opt.input);
    std::optional<Picture> background;
    if (!opt.background.empty())
        background = opt.background == opt.input ? input : load(opt.background);
    writePicture(out,
                 falseColorPicture(input, background ? &*background : nullptr, opt, commandLine));
}

}  // namespace rp
