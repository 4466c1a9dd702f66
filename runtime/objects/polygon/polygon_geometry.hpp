// POV-Ray's polygon { n, points... } in object space: one or more closed
// outlines in a common plane (see outline.hpp for how a point list splits
// into outlines), filled by the even-odd rule.
//
// The plane's normal side is POV-Ray's: the direction of
// cross(P_i - P_0, P_j - P_0) for the first point P_i unlike P_0 and the first
// later P_j not in line with them; its direction is taken from the most
// perpendicular pair (better conditioned), its sign from that first pair.
// Hits: part 0; normal = that unit normal, whichever side the ray comes from;
// uv = the hit point's coordinates (from P_0) along e1 = the unit direction
// P_i - P_0 and e2 = normal x e1 (POV-Ray's own in-plane frame; it defines
// no uv_mapping). inside: always false (flat). Fewer than three points, or
// all in line, is an empty shape.
//
// Accuracy: the plane hit from an origin moved next to the polygon: s to a
// few ulps, the point on the plane to ulps of its coordinates; a ray parallel
// to the plane has no hit. Inside or not is decided as the watertight
// triangle test decides it (Woop et al.): in the ray's sheared frame, with
// signs from difference_of_products, so polygons sharing an edge never let a
// ray slip between them. Like that test, the edges are placed to ulps of
// |vertex - ray origin|, which from a far origin is coarser than the point.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

// The polygon's plane (see above) and the 2D axes kept when projecting.
struct PolygonPlane {
    glm::dvec3 origin;  // P_0
    glm::dvec3 normal;  // unit
    glm::dvec3 e1, e2;  // in-plane unit axes for uv
    int kx, ky;         // the two axes kept when projecting to 2D
};

struct PolygonGeometry {
    std::vector<glm::dvec3> points;

    // What every intersection needs and the points alone fix: filled by
    // prepare_polygon() for a polygon intersected many times (the model
    // does it); computed per call when absent.
    struct Prepared {
        bool has_plane = false;
        PolygonPlane plane{};
        Box3 bounds{};
        // The outlines' edges as list indices (outline.hpp's rule), and the
        // points that end one: a ray projects each of those once.
        std::vector<std::array<std::uint32_t, 2>> edges;
        std::vector<std::uint32_t> ends;
    };
    std::optional<Prepared> prepared = std::nullopt;
};

// Fills polygon.prepared from its points (call again after changing them).
PolygonGeometry& prepare_polygon(PolygonGeometry& polygon);

std::optional<SurfaceHit> intersect(const PolygonGeometry& polygon, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const PolygonGeometry& polygon, glm::dvec3 p);
Box3 object_bounds(const PolygonGeometry& polygon);
bool surface_may_meet(const PolygonGeometry& polygon, const Box3& box);

}  // namespace hexant::runtime::geometry
