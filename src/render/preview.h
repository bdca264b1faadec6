// A quick geometry preview: first hits shaded by an eye light and coloured by their
// material's reflectance (or emission). It checks that a scene loads, traces and looks
// right long before lighting is involved; it is not a lighting simulation (rpict is).
#pragma once

#include "geometry/scene_geometry.h"
#include "image/picture.h"
#include "image/view.h"
#include "scene/primitive.h"

namespace rp {

struct PreviewOptions {
    View view;
    int xres = 512;
    int yres = 512;
};

struct PreviewStats {
    long rays = 0;
    long hits = 0;
    double seconds = 0;
};

// Renders one primary ray per pixel, in parallel. The picture's aspect follows the view
// (the larger of xres/yres is kept, as rpict does with -pa 1).
Picture renderPreview(const Scene& scene, const SceneGeometry& geometry,
                      const PreviewOptions& options, PreviewStats* stats = nullptr);

// The colour the preview gives a surface with modifier `modifier`: the reflectance of
// plastic/metal/trans/mirror/glass-like materials, the normalised emission of light
// sources, mid grey for anything else (mixtures, void).
Pixel previewColour(const Scene& scene, int32_t modifier);

}  // namespace rp
