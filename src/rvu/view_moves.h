// How rvu's commands change a view (RADIANCE rv2.c getrotate/getorigin, rv3.c zoomview
// and moveview): zooming by a factor for every view type, turning and tilting the view
// direction, and moving or pivoting the view point relative to a point of interest.
// Pure functions on View (image/view.h), whose direction's length is the focal
// distance; the results are not validated (the caller's ViewRays does that).
#pragma once

#include "image/view.h"
#include "util/vec.h"

namespace rp::rvu {

// v rotated about unit `axis` by `radians`, right-handed (RADIANCE spinvector).
Vec3 spinVector(const Vec3& v, const Vec3& axis, double radians);
// v turned by `radians` along the great circle towards `target`, keeping its length
// (RADIANCE geodesic, GEOD_RAD); v unchanged when the two are parallel.
Vec3 geodesic(const Vec3& v, const Vec3& target, double radians);

// Magnifies the view by `factor` (> 0): narrower angles or a smaller parallel size, as
// each view type defines magnification (RADIANCE zoomview).
void zoomView(View& view, double factor);

// rvu's rotate: turns the view direction `angle` degrees to the left about the up vector,
// then `elev` degrees up, then zooms by `zoom`.
View rotateView(const View& view, double angle, double elev, double zoom);

// rvu's aim: looks along unit `direction` (the view point stays), zoomed by `zoom`.
View aimView(const View& view, const Vec3& direction, double zoom);

// rvu's move and pivot (RADIANCE moveview): turns the direction `angle` degrees about
// the up vector and `elev` degrees down (the view point rises to look down), then puts
// the view point `mag` times closer to `center` along the new direction. Clipping
// distances follow; a parallel view is magnified instead of moved.
View moveView(const View& view, double angle, double elev, double mag, const Vec3& center);

// rvu's origin with a distance: the view point moved `distance` along the view direction.
View advanceView(const View& view, double distance);

// rvu's origin at a point: the view point at `point`, looking along unit `direction`; the
// up vector is replaced by the axis least aligned with the direction when the two
// would be parallel.
View placeView(const View& view, const Vec3& point, const Vec3& direction);

}  // namespace rp::rvu
