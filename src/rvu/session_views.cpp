// rvu's view commands: aim move rotate pivot origin focus view last L V (see session.h).
#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "material/type_traits.h"
#include "rvu/session.h"
#include "rvu/session_words.h"
#include "rvu/view_moves.h"

namespace rp::rvu {

namespace {

// RADIANCE compat (rv3.c getinterest): a magnification; negative zooms out.
std::optional<double> magnification(const std::vector<std::string>& words, size_t at,
                                    CommandResult& result) {
    if (words.size() <= at) return 1.0;
    double m = number(words[at], "magnification");
    if (m < -1e-6) return -1 / m;
    if (m <= 1e-6) {
        result = failure("illegal magnification");
        return std::nullopt;
    }
    return m;
}

// An x y z triple at words[at..at+3), if all three are there.
std::optional<Vec3> triple(const std::vector<std::string>& words, size_t at, const char* what) {
    if (words.size() < at + 3) return std::nullopt;
    return Vec3{number(words[at], what), number(words[at + 1], what), number(words[at + 2], what)};
}

}  // namespace

std::optional<render::RayResult> Session::pickSurface(const Cursor& c, CommandResult& result,
                                                      bool skipTransparent) {
    const Cursor p = clampCursor(c, image_->width(), image_->height());
    ViewRays rays(image_->view());
    auto ray = rays.ray((p.x + 0.5) / image_->width(), (p.y + 0.5) / image_->height());
    if (!ray) {
        result = failure("not on image");
        return std::nullopt;
    }
    const Scene& scene = *setup_.scene;
    Vec3 org = ray->origin;
    double travelled = 0;
    const double aft = ray->maxDistance > 0 ? ray->maxDistance : HUGE_VAL;
    std::optional<render::RayResult> weak;
    // RADIANCE compat (getinterest): invisible surfaces are passed, transparent ones
    // remembered and passed, the first solid surface taken.
    for (int step = 0; step < 64; ++step) {
        render::RayResult r =
            passes_[0]->trace(*contexts_[0], org, ray->direction, 0, nullptr, aft - travelled);
        if (!r.hit) break;
        const bool invisible = r.material < 0;  // void: nothing to see
        const bool through =
            invisible || isTransparentMaterial(scene.prims[size_t(r.material)].type);
        if (!skipTransparent || !through) return r;
        if (!invisible && !material::typeTraits(scene.prims[size_t(r.material)].type).mist && !weak)
            weak = r;
        // Continue just past the surface (relative step: the scene may be far from 0).
        const double past = r.distance * (1 + 1e-9) + 1e-7;
        org = org + ray->direction * past;
        travelled += past;
    }
    if (weak) return weak;
    result = failure("not a local object");
    return std::nullopt;
}

std::optional<Vec3> Session::interest(const std::vector<std::string>& words, size_t at,
                                      bool direction, const std::vector<Cursor>& cursor,
                                      CommandResult& result) {
    if (auto xyz = triple(words, at, "point")) {
        if (!direction) return xyz;
        const Vec3 d = *xyz - view_.point;
        if (length(d) == 0) {
            result = failure("point at view origin");
            return std::nullopt;
        }
        return normalize(d);
    }
    if (words.size() > at) {
        result = failure("expected x y z");
        return std::nullopt;
    }
    if (cursor.empty()) {
        result = pickRequest("Pick view center", 1);
        return std::nullopt;
    }
    const Cursor c = clampCursor(cursor[0], image_->width(), image_->height());
    if (direction && image_->view().type != ViewType::kParallel) {
        ViewRays rays(image_->view());
        auto ray = rays.ray((c.x + 0.5) / image_->width(), (c.y + 0.5) / image_->height());
        if (!ray) {
            result = failure("not on image");
            return std::nullopt;
        }
        return ray->direction;
    }
    auto hit = pickSurface(c, result, true);
    if (!hit) return std::nullopt;
    if (!direction) return hit->point;
    return normalize(hit->point - view_.point);
}

CommandResult Session::aim(const std::string& args, const std::vector<Cursor>& cursor) {
    const auto words = splitWords(args);
    CommandResult r;
    auto mag = magnification(words, 0, r);
    if (!mag) return r;
    auto dir = interest(words, 1, true, cursor, r);
    if (!dir) return r;
    return changeView(aimView(view_, *dir, *mag));
}

CommandResult Session::move(const std::string& args, const std::vector<Cursor>& cursor) {
    const auto words = splitWords(args);
    CommandResult r;
    auto mag = magnification(words, 0, r);
    if (!mag) return r;
    auto center = interest(words, 1, false, cursor, r);
    if (!center) return r;
    return changeView(moveView(view_, 0, 0, *mag, *center));
}

CommandResult Session::rotate(const std::string& args) {
    const auto words = splitWords(args);
    if (words.empty()) return failure("missing angle");
    if (words.size() > 3) return failure("rotate: expected angle [elev [mag]]");
    const double angle = number(words[0], "angle");
    const double elev = words.size() > 1 ? number(words[1], "elevation") : 0;
    const double zoom = words.size() > 2 ? number(words[2], "magnification") : 1;
    if (!(zoom > 1e-6)) return failure("illegal magnification");
    return changeView(rotateView(view_, angle, elev, zoom));
}

CommandResult Session::pivot(const std::string& args, const std::vector<Cursor>& cursor) {
    const auto words = splitWords(args);
    if (words.empty()) return failure("missing angle");
    const double angle = number(words[0], "angle");
    const double elev = words.size() > 1 ? number(words[1], "elevation") : 0;
    CommandResult r;
    auto mag = magnification(words, 2, r);
    if (!mag) return r;
    auto center = interest(words, 3, false, cursor, r);
    if (!center) return r;
    return changeView(moveView(view_, angle, elev, *mag, *center));
}

CommandResult Session::origin(const std::string& args, const std::vector<Cursor>& cursor) {
    // RADIANCE compat (rv2.c getorigin).
    const auto words = splitWords(args);
    if (words.size() == 1) return changeView(advanceView(view_, number(words[0], "distance")));
    if (auto point = triple(words, 0, "origin")) {
        Vec3 dir = normalize(view_.direction);
        if (auto d = triple(words, 3, "direction"); d && length(*d) > 0) dir = normalize(*d);
        return changeView(placeView(view_, *point, dir));
    }
    if (!words.empty()) return failure("origin: expected d, or xo yo zo [xd yd zd]");
    if (cursor.empty()) return pickRequest("Pick point on surface for new origin", 1);
    CommandResult r;
    auto hit = pickSurface(cursor[0], r, false);
    if (!hit) return r;
    Vec3 n = normalize(hit->unperturbedNormal);
    if (dot(n, hit->direction) > 0) n = -n;  // do not look through the other side
    return changeView(placeView(view_, hit->point + n * 2e-5, n));
}

CommandResult Session::focus(const std::string& args, const std::vector<Cursor>& cursor) {
    const auto words = splitWords(args);
    double dist = 0;
    if (!words.empty()) {
        dist = number(words[0], "focus distance");
        if (dist <= 0) return failure("focus distance must be positive");
    } else if (cursor.empty()) {
        return pickRequest("Pick focus point", 1);
    } else {
        CommandResult r;
        auto hit = pickSurface(cursor[0], r, false);
        if (!hit) return r;
        dist = hit->distance;
    }
    // Only rpict -pd uses the focal distance: the picture stays.
    view_.direction = normalize(view_.direction) * dist;
    return success(fmt::format("Focus distance set to {:f}", dist));
}

CommandResult Session::viewCommand(const std::string& args) {
    const std::string s = trim(args);
    if (s.empty()) return success("VIEW=" + formatView(view_));
    if (s[0] == '-') {
        View v = view_;
        if (applyViewString(v, s) == 0) return failure("bad view option(s)");
        return changeView(v);
    }
    // A file: append this view with the comments after the name (RADIANCE's view file).
    const auto words = splitWords(s);
    std::ofstream out(words[0], std::ios::app);
    std::string rest;
    for (size_t i = 1; i < words.size(); ++i) rest += " " + words[i];
    if (out) out << "rvu" << formatView(view_) << rest << '\n';
    if (!out) return failure("cannot open \"" + words[0] + "\"");
    return success("");
}

CommandResult Session::last(const std::string& args) {
    const auto words = splitWords(args);
    if (!words.empty()) {
        View v;  // RADIANCE compat (rv2.c lastview): the file's view over the defaults
        readViewFile(v, words[0]);
        return changeView(v);
    }
    if (!oldView_) return failure("no previous view");
    std::swap(*oldView_, view_);
    restartImage();
    return success("");
}

}  // namespace rp::rvu
