// RADIANCE pictures in memory (float pixels, top row first) and their files: header
// fields (FORMAT, EXPOSURE, PIXASPECT, PRIMARIES, COLORCORR), the resolution string in
// its 8 orientations, and reading/writing scanlines. Views (VIEW=) live in view.h;
// the pixel codecs in rgbe.h.
#pragma once

#include <array>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "image/rgbe.h"
#include "util/header.h"

namespace rp {

enum class PictureFormat { kRgbe, kXyze };

constexpr const char* kRgbeFormat = "32-bit_rle_rgbe";
constexpr const char* kXyzeFormat = "32-bit_rle_xyze";

// The resolution string after a picture header: "-Y 480 +X 640" (standard: scanlines
// run left to right, top to bottom) or any of the 8 orderings. xres is always the
// image width and yres its height (RADIANCE's RESOLU).
struct Resolution {
    int xres = 0;
    int yres = 0;
    bool yMajor = true;        // scanlines run along X ("Y" written first)
    bool xDecreasing = false;  // "-X": right to left
    bool yDecreasing = true;   // "-Y": top to bottom

    int scanlineLength() const { return yMajor ? xres : yres; }
    int scanlineCount() const { return yMajor ? yres : xres; }
    bool operator==(const Resolution&) const = default;
};

// Parses "-Y 480 +X 640" etc. (surrounding white space allowed); nullopt when the line is
// not a resolution string or a size is not a positive integer.
std::optional<Resolution> parseResolution(const std::string& line);
// Reads the resolution line after a header (InputError naming `what` when it is missing,
// malformed or too large); `text`, if given, receives the line as written.
Resolution readResolution(std::istream& in, const std::string& what, std::string* text = nullptr);
// "-Y      480 +X      640": sizes in 8 columns, as RADIANCE 6's rtrace and rcomb write
// the line (fputsresolu); readers take either.
std::string paddedResolution(const Resolution& r);
// "-Y 480 +X 640" (no newline), as RADIANCE's resolu2str.
std::string formatResolution(const Resolution& r);

struct Picture {
    int width = 0;
    int height = 0;
    PictureFormat format = PictureFormat::kRgbe;
    // Header lines other than FORMAT= (writePicture adds FORMAT= from `format`).
    // EXPOSURE= etc. stay here, in order, so tools can append to the history as
    // RADIANCE's do.
    Header header;
    std::vector<Pixel> pixels;  // width*height, row-major, top row first

    Picture() = default;
    Picture(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h) {}

    // x from the left, y from the top.
    Pixel& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    const Pixel& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }

    // Product of all EXPOSURE= values (1 if none). Pixel values in the file have been
    // multiplied by it; divide by it to get radiance.
    double exposure() const;
    // Component-wise product of all COLORCORR= triples (1 1 1 if none).
    std::array<double, 3> colorCorrection() const;
    // Product of PIXASPECT= values (pixel height over width; 1 if none).
    double pixelAspect() const;
    // The last PRIMARIES= line: red, green, blue, white chromaticities (x y each).
    std::optional<std::array<double, 8>> primaries() const;

    // Appends "EXPOSURE=<e>" to the header (and does not touch pixels).
    void addExposure(double e);
};

// Reads a picture; `what` names the source in errors. Throws InputError for anything
// that is not a complete RADIANCE RGBE/XYZE picture (no header, other FORMAT, bad
// resolution line, truncated or corrupt scanlines, malformed EXPOSURE etc.).
Picture readPicture(std::istream& in, const std::string& what);
Picture readPicture(const std::string& path);

// Reads only the header and resolution line (for getinfo -d and quick checks).
struct PictureInfo {
    Header header;
    PictureFormat format = PictureFormat::kRgbe;
    Resolution resolution;
};
PictureInfo readPictureInfo(std::istream& in, const std::string& what);

// Writes header (plus FORMAT=), standard resolution string and RLE scanlines.
void writePicture(std::ostream& out, const Picture& pic);
// Writes to a temporary file in the target folder and renames it over `path` when
// complete, so a failed run never leaves a half-written picture. Throws InputError when
// the file cannot be written.
void writePicture(const std::string& path, const Picture& pic);

}  // namespace rp
