// Scene records -> shape arrays (see shapes.h).
#include "geometry/shapes.h"

#include <string>

namespace rp {

ShapeSet buildShapes(const Scene& scene, int32_t begin, int32_t end) {
    ShapeSet set;
    for (size_t i = size_t(begin); i < size_t(end); ++i) {
        const Primitive& p = scene.prims[i];
        if (!isSurface(p.type)) continue;
        int32_t index = int32_t(i);
        switch (p.type) {
            case PrimType::Polygon: {
                PolygonShape shape;
                size_t firstTri = set.triangles.size();
                size_t firstVert = set.vertices.size();
                if (makePolygon(p, index, shape, set.vertices, set.triangles)) {
                    set.trianglePolygon.resize(set.triangles.size(), uint32_t(set.polygons.size()));
                    set.polygons.push_back(shape);
                    for (size_t v = firstVert; v < set.vertices.size(); ++v)
                        set.bounds.extend(set.vertices[v]);
                } else {
                    set.triangles.resize(firstTri);
                    set.vertices.resize(firstVert);
                }
                break;
            }
            case PrimType::Sphere:
            case PrimType::Bubble: {
                SphereShape shape;
                if (makeSphere(p, index, shape)) {
                    set.spheres.push_back(shape);
                    set.bounds.extend(sphereBounds(shape));
                }
                break;
            }
            case PrimType::Cone:
            case PrimType::Cup:
            case PrimType::Cylinder:
            case PrimType::Tube: {
                ConeShape shape;
                if (makeCone(p, index, shape)) {
                    set.cones.push_back(shape);
                    set.bounds.extend(coneBounds(shape));
                }
                break;
            }
            case PrimType::Ring: {
                RingShape shape;
                if (makeRing(p, index, shape)) {
                    set.rings.push_back(shape);
                    set.bounds.extend(ringBounds(shape));
                }
                break;
            }
            case PrimType::Source: {
                DistantSource src;
                if (makeSource(p, index, src) && p.object < 0) set.sources.push_back(src);
                break;
            }
            case PrimType::Instance:
            case PrimType::Mesh:
                break;
            default:
                RP_CHECK(false);  // every surface type is handled above
        }
    }
    return set;
}

}  // namespace rp
