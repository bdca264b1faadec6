// RADIANCE view parameters (-vt -vp -vd -vu -vh -vv -vo -va -vs -vl -vf): parsing from
// the command line, from VIEW= header lines and view files, formatting back, validation,
// and the image-plane-to-ray mapping of each view type (RADIANCE's image.c). Pictures
// themselves live in picture.h.
#pragma once

#include <optional>
#include <string>

#include "util/header.h"
#include "util/options.h"
#include "util/vec.h"

namespace rp {

// The letter after -vt.
enum class ViewType : char {
    kPerspective = 'v',
    kParallel = 'l',
    kCylindrical = 'c',    // panorama: angular horizontally, perspective vertically
    kHemispherical = 'h',  // fisheye: image radius proportional to sin(angle)
    kAngular = 'a',        // fisheye: image radius proportional to angle
    kPlanisphere = 's',    // fisheye: stereographic, radius proportional to tan(angle/2)
};

// Defaults are rpict's (STDVIEW in RADIANCE's view.h).
struct View {
    ViewType type = ViewType::kPerspective;
    Vec3 point{0, 0, 0};      // -vp
    Vec3 direction{0, 1, 0};  // -vd; its length is the focal distance (-pd)
    Vec3 up{0, 0, 1};         // -vu
    double horizontal = 45;   // -vh: degrees, or world width for parallel views
    double vertical = 45;     // -vv
    double fore = 0;          // -vo: fore clipping distance (0 = none)
    double aft = 0;           // -va: aft clipping distance (0 = none)
    double shift = 0;         // -vs: image shift right, in image widths
    double lift = 0;          // -vl: image lift up, in image heights

    bool operator==(const View&) const = default;
};

// Parses one view option at argv[0] (argv[1..argc) are the following arguments).
// Returns how many entries it consumed including the option itself (1 for -vtX, 2 for
// -vh 30 and -vf file, 4 for -vp x y z), or 0 when argv[0] is not a view option (so
// the caller can try its own options). Missing or non-numeric values, an unknown view
// type, and unreadable view files throw InputError.
int parseViewOption(View& view, int argc, const char* const* argv);

// The view options as one entry of a tool's option table (util/options.h): the words
// parseViewOption takes (-vt?, -vp -vd -vu -vh -vv -vo -va -vs -vl -vf), read by it.
OptionSpec viewOptionSpec(View& view);

// Applies the view options found in `text` in order, skipping other words, like
// RADIANCE's sscanview; `text` may be a VIEW= value ("-vtv -vp 1 2 3 ..."), a saved rvu
// "view" line or a command line. Returns the number of options applied. Throws
// InputError for a recognised option with bad values.
int applyViewString(View& view, const std::string& text);

// True for lines that carry view options: "VIEW=..." or the command line of rpict,
// rview, rvu, rpiece or pinterp (RADIANCE's isview). rpict -S reads such lines.
bool isViewLine(const std::string& line);

// The view described by a header: defaults, then every "VIEW=" line (and rpict/rvu
// command lines) applied in order, as RADIANCE's viewfile. nullopt if none.
std::optional<View> viewFromHeader(const Header& header);

// Reads -vf files: a RADIANCE file with a header (picture, view file from rvu) uses the
// header's views; a plain text file is read as lines of view options. Options found
// are applied on top of `view`. Throws InputError if the file cannot be read or holds
// no view options.
void readViewFile(View& view, const std::string& path);

// All options, " -vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 45 -vv 45 -vo 0 -va 0 -vs 0
// -vl 0" (leading space, %.6g numbers), as RADIANCE's fprintview.
std::string formatView(const View& view);
// Only the options that differ from the defaults, as RADIANCE's viewopt.
std::string formatViewMinimal(const View& view);
// "VIEW=" + formatView(view): the header line rpict writes.
std::string viewHeaderLine(const View& view);

// The image-plane extents RADIANCE's setview computes for the view's type and sizes
// (-vh, -vv): plane widths for v/l/h, angles in radians for a, horizontally for c.
// No range checks (ViewRays makes them); their ratio v/h is the picture's aspect.
struct ImagePlaneSize {
    double horizontal = 1, vertical = 1;
};
ImagePlaneSize imagePlaneSize(const View& view);

// A validated view ready for ray generation (RADIANCE's setview).
class ViewRays {
public:
    // Throws InputError (without file location) with RADIANCE's setview messages: zero
    // view direction, zero view up vector, view up parallel to view direction, illegal
    // horizontal/vertical view size (<= 0, or too large for the type), illegal
    // fore/aft clipping plane.
    explicit ViewRays(const View& view);

    struct Ray {
        Vec3 origin;
        Vec3 direction;      // unit length
        double maxDistance;  // from the aft clipping plane; 0 = unlimited
    };

    // The ray through image location (x, y): x from 0 (left) to 1 (right), y from 0
    // (bottom) to 1 (top), before -vs/-vl are added. nullopt outside the fisheye circle
    // (RADIANCE's viewray returns -1 there).
    std::optional<Ray> ray(double x, double y) const;

    // Depth of field (rpict -pd; RADIANCE's jitteraperture in image.c): moves the origin
    // of `ray` (as ray() made it) to a point of a disk of diameter `diameter` facing the
    // view, chosen by (u1, u2) in [0,1)^2, and aims it at the point the unmoved ray
    // reaches at the focal distance (the length of -vd), so that only surfaces at that
    // distance stay sharp. Fisheye and panoramic views also move the origin along the
    // view direction by up to pi/8 diameters (u3). Returns false when the new direction
    // is degenerate. No change for diameter <= 1e-6.
    bool jitterAperture(Ray& ray, double diameter, double u1, double u2, double u3) const;

    // Where world point `p` appears (RADIANCE's viewloc, the inverse of ray()): image
    // coordinates as ray() takes them (-vs/-vl included) and the distance along its ray
    // from the fore clipping plane (negative behind the view). nullopt where the point
    // has no image: on the perspective view's plane, behind a planisphere, at the
    // panorama's axis.
    struct Location {
        double x = 0, y = 0;
        double depth = 0;
        bool behind = false;   // depth <= 0
        bool beyond = false;   // past the aft clipping plane
        bool outside = false;  // not strictly inside the image square (0,1)^2
        bool good() const { return !behind && !beyond && !outside; }
    };
    std::optional<Location> locate(const Vec3& p) const;

    const View& view() const { return view_; }
    const Vec3& horizontalVector() const { return hvec_; }
    const Vec3& verticalVector() const { return vvec_; }
    double focalDistance() const { return focalDistance_; }

private:
    // locate() for the angular and planispheric fisheyes: x and y of unit direction `dir`
    // from the view point; false where it has no image.
    bool locateFisheye(const Vec3& dir, Location& loc) const;

    View view_;
    Vec3 dir_;                  // unit view direction
    Vec3 hvec_;                 // right vector, scaled by the image-plane width except for a, s, c
    Vec3 vvec_;                 // up vector, scaled by the image-plane height except for a, s
    double hn2_ = 0, vn2_ = 0;  // squared image-plane sizes (RADIANCE's hn2, vn2)
    double focalDistance_ = 1;
};

}  // namespace rp
