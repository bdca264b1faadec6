// One rvu run without its display: the scene's renderer, the current and previous view,
// the exposure, the progressively refined picture, and RADIANCE rvu's commands (rv2.c,
// rv3.c, rview.c): aim, move, rotate, pivot, origin, view, last, L, V, exposure, focus,
// frame, set, new, trace, write, redraw, free, quit. Commands that need the pointer
// (rvu's cursor) say so and take its positions with the command (the display asks the
// user). Not thread safe: the display runs commands and refinement on one thread.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "render/renderer.h"
#include "render/spectral_passes.h"
#include "rvu/progressive.h"
#include "rvu/rvu_options.h"
#include "scene/primitive.h"
#include "util/spectrum.h"

namespace rp::rvu {

// A pointer position on the picture: x from the left, y from the bottom (RADIANCE's
// device coordinates), in pixels.
struct Cursor {
    int x = 0, y = 0;
};

struct CommandResult {
    bool ok = true;
    std::string output;  // what rvu prints (may be several lines)
    std::string error;   // why the command failed (ok false)
    // Non-empty: the command needs `points` pointer positions; run it again with them.
    std::string pick;
    int points = 0;
    bool quit = false;
};

struct SessionSetup {
    const Scene* scene = nullptr;
    const SceneGeometry* geometry = nullptr;
    std::vector<std::string> searchPath;  // for the renderer's function and data files
    RvuOptions options;
    // The start of the first header line of written pictures and views ("rvu" and the
    // options), and the scene's name after the view.
    std::string commandLine = "rvu";
    std::string sceneName;
};

class Session {
public:
    // Builds the renderer and the first (untraced) picture. Throws InputError for an
    // invalid view or what the renderer refuses.
    explicit Session(SessionSetup setup);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // Runs one command line. Never throws for bad input: errors come back in the result.
    CommandResult execute(const std::string& line, const std::vector<Cursor>& cursor = {});

    // Refines the picture by (the rest of) one level; see ProgressiveImage::refineLevel.
    bool refine(const std::function<bool()>& interrupted, const std::function<void()>& progress);
    bool done() const { return image_->done(); }
    // rvu's progress line: "8 refining...", "64 sampling..." or "done".
    std::string status() const;

    const ProgressiveImage& image() const { return *image_; }
    const View& view() const { return view_; }
    double exposure() const { return exposure_; }
    bool greyscale() const { return greyscale_; }

private:
    CommandResult dispatch(const std::string& name, const std::string& args,
                           const std::vector<Cursor>& cursor);
    // Command families (session_commands.cpp, session_views.cpp).
    CommandResult aim(const std::string& args, const std::vector<Cursor>& cursor);
    CommandResult move(const std::string& args, const std::vector<Cursor>& cursor);
    CommandResult rotate(const std::string& args);
    CommandResult pivot(const std::string& args, const std::vector<Cursor>& cursor);
    CommandResult origin(const std::string& args, const std::vector<Cursor>& cursor);
    CommandResult viewCommand(const std::string& args);
    CommandResult last(const std::string& args);
    CommandResult loadRadView(const std::string& args);
    CommandResult saveRadView(const std::string& args);
    CommandResult exposureCommand(const std::string& args, const std::vector<Cursor>& cursor);
    CommandResult focus(const std::string& args, const std::vector<Cursor>& cursor);
    CommandResult frame(const std::string& args, const std::vector<Cursor>& cursor);
    CommandResult set(const std::string& args);
    CommandResult newImage(const std::string& args);
    CommandResult trace(const std::string& args, const std::vector<Cursor>& cursor);
    CommandResult write(const std::string& args);

    // The point of interest for aim/move/pivot (RADIANCE getinterest): `words` after the
    // magnification give x y z, or the pointer picks it. `direction`: a unit view
    // direction is wanted rather than a point. Errors and picks come back in `result`.
    std::optional<Vec3> interest(const std::vector<std::string>& words, size_t at, bool direction,
                                 const std::vector<Cursor>& cursor, CommandResult& result);
    // The first visible surface along the ray through the pointer position.
    std::optional<render::RayResult> pickSurface(const Cursor& c, CommandResult& result,
                                                 bool skipTransparent);
    // Makes `view` current (keeping the previous one for `last`) and restarts the
    // picture; an invalid view is an error and changes nothing.
    CommandResult changeView(const View& view);
    void restartImage();
    void rebuildRenderer();
    std::string pictureHeaderLine() const;

    // The ray traced in every pass of a spectral sampling (-cs above 3), gathered.
    render::RayResult traceAllPasses(const Vec3& org, const Vec3& dir, double maxDistance);

    SessionSetup setup_;
    // One renderer per pass (one for RGB; render/spectral_passes.h), each with its context
    // for this thread; the first also serves picks and geometry.
    render::PassRenderers passes_;
    std::vector<render::Renderer::ContextPtr> contexts_;
    spectral::Sampling sampling_;
    View view_;
    std::optional<View> oldView_;
    double exposure_;
    bool greyscale_;
    bool newParams_ = false;  // set changed a rendering option: new rebuilds the renderer
    std::unique_ptr<ProgressiveImage> image_;
    std::string lastPicture_;  // write's file
    std::string radFile_;      // L and V's file
};

}  // namespace rp::rvu
