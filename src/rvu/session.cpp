// rvu's session: state, command dispatch, pictures and display settings (see session.h).
// The view commands are in session_views.cpp, set/new/trace in session_params.cpp.
#include "rvu/session.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <ctime>
#include <fstream>

#include "image/picture.h"
#include "image/tonemap.h"
#include "render/rpict_tracer.h"
#include "render/spectral_passes.h"
#include "rvu/session_words.h"
#include "util/error.h"

namespace rp::rvu {

Session::Session(SessionSetup setup)
    : setup_(std::move(setup)),
      view_(setup_.options.picture.view),
      exposure_(setup_.options.exposure),
      greyscale_(setup_.options.greyscale),
      radFile_(setup_.options.radFile) {
    RP_CHECK(setup_.scene && setup_.geometry);
    ViewRays check(view_);  // before the (slower) renderer
    rebuildRenderer();
    restartImage();
}

Session::~Session() = default;

void Session::rebuildRenderer() {
    if (image_) image_->dropTracers();
    contexts_.clear();
    passes_.clear();
    // RADIANCE 6's -cs/-cw: passes of three bands, as rpict renders them.
    sampling_ = render::spectralSampling(setup_.options.picture.render);
    passes_ = render::passRenderers(*setup_.scene, *setup_.geometry, setup_.options.picture.render,
                                    sampling_, setup_.searchPath);
    for (const auto& r : passes_) contexts_.push_back(r->makeContext());
    newParams_ = false;
}

render::RayResult Session::traceAllPasses(const Vec3& org, const Vec3& dir, double maxDistance) {
    std::vector<render::RayResult> all;
    for (size_t p = 0; p < passes_.size(); ++p)
        all.push_back(passes_[p]->trace(*contexts_[p], org, dir, 0, nullptr, maxDistance));
    return all.size() == 1 ? all[0] : render::mergePasses(all, spectral::passesOf(sampling_));
}

void Session::restartImage() {
    // RADIANCE compat (rv3.c newimage): the device size fitted to the view's aspect.
    render::RpictOptions size = setup_.options.picture;
    size.view = view_;
    size.pixelAspect = 1;
    const render::PictureSize ps = render::pictureSize(size);
    const render::RpictOptions& p = setup_.options.picture;
    image_ = std::make_unique<ProgressiveImage>(view_, ps.xres, ps.yres,
                                                render::PixelRayParams{p.pixelJitter, 0, 0},
                                                p.sampleSpacing, p.sampleThreshold);
}

bool Session::refine(const std::function<bool()>& interrupted,
                     const std::function<void()>& progress) {
    const render::PixelTracerFactory tracers = render::passPixelTracers(passes_, sampling_);
    return image_->refineLevel(std::max(1, setup_.options.picture.render.threads), tracers,
                               interrupted, progress);
}

std::string Session::status() const {
    if (image_->done()) return "done";
    // RADIANCE compat (rview.c): the number of blocks across, then what the level does.
    const int across = (std::max(image_->width(), image_->height()) + image_->blockSize() - 1) /
                       image_->blockSize();
    return fmt::format("{} {}...", across, image_->sampling() ? "sampling" : "refining");
}

CommandResult Session::execute(const std::string& line, const std::vector<Cursor>& cursor) {
    std::string text = line;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    const size_t start = text.find_first_not_of(" \t");
    if (start == std::string::npos) return {};  // RADIANCE: an empty line continues
    const size_t end = text.find_first_of(" \t", start);
    const std::string name = text.substr(start, end == std::string::npos ? end : end - start);
    const std::string args = end == std::string::npos ? "" : text.substr(end + 1);
    try {
        return dispatch(name, args, cursor);
    } catch (const std::exception& e) {  // bad input from a command never ends rvu
        return failure(name + ": " + e.what());
    }
}

namespace {

// RADIANCE compat (rview.c command): a command may be abbreviated to any prefix that
// starts like it; the first letter decides between the candidates in this order.
bool abbreviates(const std::string& word, const char* command) {
    return !word.empty() && std::string(command).compare(0, word.size(), word) == 0;
}

}  // namespace

CommandResult Session::dispatch(const std::string& name, const std::string& args,
                                const std::vector<Cursor>& cursor) {
    auto is = [&](const char* c) { return abbreviates(name, c); };
    if (is("aim")) return aim(args, cursor);
    if (is("exposure")) return exposureCommand(args, cursor);
    if (is("frame")) return frame(args, cursor);
    if (is("focus")) return focus(args, cursor);
    if (is("free")) return success("");  // nothing cached that could be freed
    if (is("last")) return last(args);
    if (name == "L") return loadRadView(args);
    if (name == "V") return saveRadView(args);
    if (is("move")) return move(args, cursor);
    if (is("new")) return newImage(args);
    if (is("origin")) return origin(args, cursor);
    if (is("pivot")) return pivot(args, cursor);
    if (is("quit")) {
        CommandResult r;
        r.quit = true;
        return r;
    }
    if (is("rotate")) return rotate(args);
    if (is("repaint") || is("redraw") || name == "\x12") return success("");  // ^R
    if (is("set")) return set(args);
    if (is("trace")) return trace(args, cursor);
    if (is("view")) return viewCommand(args);
    if (is("write")) return write(args);
    if (is("pause") || is("stop")) return failure(name + ": not available in a web page");
    return failure(name + ": unknown command");
}

CommandResult Session::changeView(const View& view) {
    try {
        ViewRays check(view);
    } catch (const InputError& e) {
        return failure(std::string("view not set - ") + e.what());
    }
    // RADIANCE compat (rv3.c newview): an unchanged view keeps the picture.
    if (view == view_) return success("");
    oldView_ = view_;
    view_ = view;
    restartImage();
    return success("");
}

CommandResult Session::exposureCommand(const std::string& args, const std::vector<Cursor>& cursor) {
    // RADIANCE compat (rv2.c getexposure). A plain number or f-stops set the exposure
    // relative to the one that makes the reference 0.5 (the picture's average, or the
    // pixel picked); '=' sets it absolutely; '@' adapts to what the eye would see.
    std::string s = trim(args);
    bool adapt = false;
    if (!s.empty() && s[0] == '@') {
        adapt = true;
        s = trim(s.substr(1));
    }
    double e = 1;
    std::optional<Pixel> reference;
    if (s.empty()) {
        if (cursor.empty()) return pickRequest("Pick point for exposure", 1);
        const Cursor c = clampCursor(cursor[0], image_->width(), image_->height());
        reference = image_->pixels()[size_t(image_->height() - 1 - c.y) * size_t(image_->width()) +
                                     size_t(c.x)];
    } else {
        bool absolute = false;
        if (s[0] == '=') {
            absolute = true;
            s = trim(s.substr(1));
            if (s.empty()) return success(fmt::format("exposure ({:f})", exposure_));
        }
        const double v = number(s, "exposure");
        e = (s[0] == '+' || s[0] == '-') ? std::pow(2.0, v) : v;
        if (!absolute) reference = averagePixel(image_->pixels());
    }
    if (reference) {
        const double b = pixelBrightness(*reference);  // our pixels are not pre-exposed
        if (b < 1e-15) return failure("cannot normalize to zero");
        // RADIANCE's luminance is 179 lm/W times brightness (WHTEFFICACY).
        e *= adapt ? 106.0 / std::pow(1.219 + std::pow(179.0 * b, 0.4), 2.5) : 0.5 / b;
    }
    if (!(e > 1e-6) || !std::isfinite(e)) return failure("exposure: out of range");
    exposure_ = e;
    return success(fmt::format("exposure {:g}", exposure_));
}

CommandResult Session::frame(const std::string& args, const std::vector<Cursor>& cursor) {
    // RADIANCE compat (rv3.c getrect): "all", four numbers, or two picked corners.
    const std::string s = trim(args);
    const int w = image_->width(), h = image_->height();
    if (!s.empty() && abbreviates(s, "all")) {
        image_->setFrame(PixelRect{0, 0, w, h});
        return success("");
    }
    std::vector<Cursor> corners;
    const std::vector<std::string> words = splitWords(s);
    if (words.size() == 4) {
        corners = {{int(number(words[0], "frame")), int(number(words[1], "frame"))},
                   {int(number(words[2], "frame")), int(number(words[3], "frame"))}};
    } else if (!words.empty()) {
        return failure("frame: expected xmin ymin xmax ymax, or all");
    } else if (cursor.size() < 2) {
        return pickRequest("Pick first corner, then second corner", 2);
    } else {
        corners = {cursor[0], cursor[1]};
    }
    const int x0 = std::min(corners[0].x, corners[1].x), x1 = std::max(corners[0].x, corners[1].x);
    const int y0 = std::min(corners[0].y, corners[1].y), y1 = std::max(corners[0].y, corners[1].y);
    // y counts from the bottom; rows from the top.
    image_->setFrame(PixelRect{x0, h - y1, x1, h - y0});
    return success("");
}

CommandResult Session::write(const std::string& args) {
    const std::vector<std::string> words = splitWords(args);
    if (!words.empty()) lastPicture_ = words[0];
    if (lastPicture_.empty()) return failure("write: no file");
    // RADIANCE compat (rv2.c writepict): the view and scene on the first line, the
    // exposure applied to the pixels and recorded.
    Picture pic(image_->width(), image_->height());
    const float scale = float(exposure_);
    for (size_t i = 0; i < pic.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) pic.pixels[i][c] = image_->pixels()[i][c] * scale;
    render::addRpictHeader(pic, pictureHeaderLine(), std::time(nullptr));
    if (exposure_ != 1) pic.header.lines.push_back(fmt::format("EXPOSURE={:e}", exposure_));
    writePicture(lastPicture_, pic);
    return success("wrote \"" + lastPicture_ + "\"");
}

std::string Session::pictureHeaderLine() const {
    std::string line = setup_.commandLine + formatView(view_);
    if (!setup_.sceneName.empty()) line += " " + setup_.sceneName;
    return line;
}

}  // namespace rp::rvu
